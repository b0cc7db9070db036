"""Classes whose code is a Python script (Ikaros 3 ``<class python="script.py">``).

The class's ports and parameters come from its .ikc file; its script defines hook
functions (``init``, ``tick``, ``shutdown``, ``command``) and runs in a worker process per
module, with the interpreter of ``python_executable``. See docs/python-scripts.md.
"""
from __future__ import annotations

import hashlib
import os
import re

from ..description import ClassDescription, ParameterSpec
from .module import ON_ERROR, ScriptedModule

__all__ = ["ScriptedModule", "script_class", "script_of"]

# the settings of a scripted class: parameters besides the .ikc's, whose defaults the
# <class> element may set (on_error="zero")
SETTINGS = (
    ("on_error", "list", "fail", "what a failing hook does: fail ends the run, zero sets "
                                 "the outputs to 0, log keeps them; the error is logged",
     list(ON_ERROR)),
    ("restart_on_crash", "bool", "no", "start the worker again (and its init) if it dies", []),
    ("use_global_names", "bool", "no", "the inputs, outputs and parameters are globals of "
                                       "the script too", []),
    ("python_executable", "string", "", "the Python interpreter that runs the script "
                                        "(default: the kernel's own)", []),
)


def script_of(ikc: str, root_attrs: dict, defines_module) -> str | None:
    """The script of a class file: its ``python`` attribute (relative to the .ikc), or a
    ``<Class>.py`` beside it that defines a ``tick`` function and is not a module of this
    project's API (``defines_module(path)``). None for a class with neither."""
    folder = os.path.dirname(os.path.abspath(ikc))
    named = root_attrs.get("python")
    if named:
        return os.path.normpath(os.path.join(folder, named))
    beside = os.path.splitext(os.path.abspath(ikc))[0] + ".py"
    try:
        with open(beside, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError):
        return None
    if re.search(r"^def tick\s*\(", text, re.MULTILINE) and not defines_module(beside):
        return beside
    return None


def script_class(description: ClassDescription, script: str,
                 class_attrs: dict) -> type[ScriptedModule]:
    """The module class of a class file whose code is ``script``: the .ikc's description
    with the scripted-class settings added (defaults from ``class_attrs``). A dynamic
    output, which a script cannot resize, is a ValueError."""
    dynamic = [o.name for o in description.outputs if o.dynamic]
    if dynamic:
        raise ValueError(f"a class written as a Python script cannot have dynamic outputs "
                         f"({', '.join(dynamic)})")
    own = tuple(p.name for p in description.parameters)
    taken = set(own)
    for name, kind, default, text, options in SETTINGS:
        if name not in taken:
            description.parameters.append(ParameterSpec(
                name, kind, class_attrs.get(name, default), text, options))
    cls = type(description.name, (ScriptedModule,), {
        "__module__": __name__, "script": script, "script_parameters": own,
        "script_digest": _digest(script)})
    description.script = script
    cls.description = description
    cls.ikc_description = True
    return cls


def _digest(script: str) -> str | None:
    """The script's text as a digest: an Apply keeps a module only when its script is
    the same (kernel/carry.py)."""
    try:
        with open(script, "rb") as f:
            return hashlib.sha1(f.read()).hexdigest()
    except OSError:
        return None
