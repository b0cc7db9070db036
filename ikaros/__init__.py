"""ikaros: system-level brain models and real-time robot control in Python.

    import ikaros
    net = ikaros.load("model.ikg", gain=2)   # keyword overrides set top-group attributes
    net.run(ticks=100)
    print(net.output("Arm.PID.OUTPUT"))

or in code:

    model = ikaros.Group("Arm", tick_duration=0.01)
    ramp = model.module("Sweep", "Ramp", step=0.1)
    pid = model.module("PIDController", "PID", Kp=0.5)
    model.connect(ramp.OUTPUT, pid.INPUT)
    net = model.build()
"""
from __future__ import annotations

from .description import ClassDescription
from .errors import ModelError, RunError
from .language.diagnostics import Diagnostics, ModelWarning
from .kernel.classes import classes as _classes
from .kernel.network import Network
from .model import Group
from .kernel.state import StateError
from .module import DynamicArray, Input, Module, Output, Parameter, State

__version__ = "0.1.0"
__all__ = ["load", "classes", "Group", "Network", "Module", "Parameter", "Input", "Output",
           "State", "DynamicArray", "ModelError", "ModelWarning", "RunError", "StateError",
           "ClassDescription",
           "open_recording", "sweep"]


def __getattr__(name: str):
    # ikaros.open_recording and ikaros.sweep (ikaros.experiments), imported when first used
    if name in ("open_recording", "sweep"):
        from . import experiments
        return getattr(experiments, name)
    raise AttributeError(f"module 'ikaros' has no attribute '{name}'")


def load(filename: str, /, *, strict: bool = False, lenient: bool = False,
         quiet: bool = False, max_memory: int | str | None = None,
         load_state: str | bool | None = None, user_data: str | None = None,
         **overrides) -> Network:
    """Read, build and initialise a model file (.ikg). Other keyword arguments set
    attributes of the top group and win over the file. Raises ModelError naming the file,
    line and element of what is wrong.

    What the original Ikaros accepts but a clean file would not say is a warning, printed
    to stderr as ``file:line: warning: ...`` (not with ``quiet=True``) and kept in
    ``net.warnings``. ``strict=True`` makes every such warning an error; ``lenient=True``
    drops connections to modules or ports that do not exist, with a warning, as Ikaros 3
    does (they are errors by default). ``max_memory`` limits the memory of all buffers
    (bytes, or text such as ``"512M"``; default half the physical memory).
    ``load_state`` (a file name, or True for ``model.state`` beside the model) loads a
    state saved with ``net.save_state`` after init, as ``ikaros -L`` does; a state that does
    not fit raises StateError (a ValueError) and the network is closed.
    ``user_data`` (``ikaros -u DIR``) is the folder where modules write files with
    relative names (default: the model file's folder); a ``user_data`` attribute in the
    file is ignored, with a warning.
    """
    net = build_tree(None, filename, strict=strict, lenient=lenient, quiet=quiet,
                     max_memory=max_memory, user_data=user_data, **overrides)
    if load_state:
        try:
            net.load_state(None if load_state is True else load_state)
        except BaseException:
            net.close()
            raise
    return net


def build_tree(tree, filename: str, *, strict: bool = False, lenient: bool = False,
               quiet: bool = False, max_memory: int | str | None = None,
               classes: dict | None = None, user_data: str | None = None,
               **overrides) -> Network:
    """Build a model tree (``tree``, or the file ``filename`` read when it is None) as
    ``load`` does. ``classes`` are Module subclasses given in code, by class name."""
    from .kernel.builder import Builder
    from .limits import LimitError, Limits
    try:
        limits = Limits().with_memory(max_memory)
    except LimitError as e:
        raise ModelError(f"max_memory: {e}") from None
    diagnostics = Diagnostics(strict=strict, lenient=lenient, quiet=quiet)
    registry = None
    if classes:
        import os
        from .kernel.codeclasses import CodeClassRegistry
        registry = CodeClassRegistry([os.path.dirname(os.path.abspath(filename))], classes)
    return Builder(filename, overrides, model=tree, diagnostics=diagnostics, limits=limits,
                   registry=registry, network_factory=_network,
                   user_data=user_data).build()


def _network(*built) -> Network:
    """A Network, or one whose groups with a ``process`` attribute run in other kernel
    processes (docs/links.md)."""
    from .links.split import make_network
    return make_network(*built)


def classes(*folders: str) -> dict[str, ClassDescription]:
    """{class name: class description} of every class found: the standard library,
    installed packages (entry point group ``ikaros.modules``) and the given folders."""
    return _classes(list(folders))
