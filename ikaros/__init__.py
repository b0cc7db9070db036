"""ikaros: system-level brain models and real-time robot control in Python.

    import ikaros
    net = ikaros.load("model.ikg", gain=2)   # keyword overrides set top-group attributes
    net.run(ticks=100)
    print(net.output("Arm.PID.OUTPUT"))
"""
from __future__ import annotations

from .description import ClassDescription
from .errors import ModelError, RunError
from .kernel.classes import classes as _classes
from .kernel.network import Network
from .module import Input, Module, Output, Parameter

__version__ = "0.1.0"
__all__ = ["load", "classes", "Network", "Module", "Parameter", "Input", "Output",
           "ModelError", "RunError", "ClassDescription"]


def load(filename: str, /, *, max_memory: int | str | None = None, **overrides) -> Network:
    """Read, build and initialise a model file (.ikg). Keyword arguments set attributes of
    the top group and win over the file. ``max_memory`` limits the memory of all buffers
    (bytes, or text such as ``"512M"``; default half the physical memory). Raises
    ModelError naming the file, line and element of what is wrong."""
    from .kernel.builder import Builder
    from .limits import LimitError, Limits
    try:
        limits = Limits().with_memory(max_memory)
    except LimitError as e:
        raise ModelError(f"max_memory: {e}") from None
    return Builder(filename, overrides, limits=limits).build()


def classes(*folders: str) -> dict[str, ClassDescription]:
    """{class name: class description} of every class found: the standard library,
    installed packages (entry point group ``ikaros.modules``) and the given folders."""
    return _classes(list(folders))
