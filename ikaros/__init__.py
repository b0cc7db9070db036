"""ikaros: system-level brain models and real-time robot control in Python.

    import ikaros
    net = ikaros.load("model.ikg", gain=2)   # keyword overrides set top-group attributes
    net.run(ticks=100)
    print(net.output("Arm.PID.OUTPUT"))
"""
from __future__ import annotations

from .description import ClassDescription
from .errors import ModelError, RunError
from .language.diagnostics import Diagnostics, ModelWarning
from .kernel.classes import classes as _classes
from .kernel.network import Network
from .module import Input, Module, Output, Parameter

__version__ = "0.1.0"
__all__ = ["load", "classes", "Network", "Module", "Parameter", "Input", "Output",
           "ModelError", "ModelWarning", "RunError", "ClassDescription"]


def load(filename: str, /, *, strict: bool = False, lenient: bool = False,
         quiet: bool = False, **overrides) -> Network:
    """Read, build and initialise a model file (.ikg). Other keyword arguments set
    attributes of the top group and win over the file. Raises ModelError naming the file,
    line and element of what is wrong.

    What the original Ikaros accepts but a clean file would not say is a warning, printed
    to stderr as ``file:line: warning: ...`` (not with ``quiet=True``) and kept in
    ``net.warnings``. ``strict=True`` makes every such warning an error; ``lenient=True``
    drops connections to modules or ports that do not exist, with a warning, as Ikaros 3
    does (they are errors by default).
    """
    from .kernel.builder import Builder
    diagnostics = Diagnostics(strict=strict, lenient=lenient, quiet=quiet)
    return Builder(filename, overrides, diagnostics=diagnostics,
                   network_factory=_network).build()


def _network(*built) -> Network:
    """A Network, or one whose groups with a ``process`` attribute run in other kernel
    processes (docs/links.md)."""
    from .links.split import make_network
    return make_network(*built)


def classes(*folders: str) -> dict[str, ClassDescription]:
    """{class name: class description} of every class found: the standard library,
    installed packages (entry point group ``ikaros.modules``) and the given folders."""
    return _classes(list(folders))
