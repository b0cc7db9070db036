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
from .language.diagnostics import ModelWarning
from .kernel.classes import classes as _classes
from .network import Network, build_tree, load  # noqa: F401  (ikaros.build_tree)
from .model import Group
from .kernel.state import StateError
from .module import DynamicArray, Input, Module, Output, Parameter, State
from .version import __version__  # noqa: F401  (ikaros.__version__)

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


def classes(*folders: str) -> dict[str, ClassDescription]:
    """{class name: class description} of every class found: the standard library,
    installed packages (entry point group ``ikaros.modules``) and the given folders."""
    return _classes(list(folders))
