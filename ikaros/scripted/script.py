"""A class's Python script in the worker: loading it, its hooks, and its globals.

Run in the worker process: it needs only the standard library and NumPy.
"""
from __future__ import annotations

import inspect
import os
import re
import traceback
from typing import Any


try:                    # imported from the ikaros package (its tests)
    from .proxy import ModuleProxy, copy_returned
except ImportError:     # in the worker, which has this folder on sys.path (worker.py)
    from proxy import ModuleProxy, copy_returned

HOOKS = ("init", "tick", "shutdown", "command")
COMMAND_ARGUMENTS = ("module", "name", "x", "y", "value")   # what command() may take
LOGGING_HELPERS = ("log", "warning", "error", "debug")
_HERE = os.path.dirname(os.path.abspath(__file__))


class ScriptError(Exception):
    """A script failed; ``traceback_text`` is the script's part of the traceback."""

    def __init__(self, message: str, traceback_text: str = ""):
        super().__init__(message)
        self.traceback_text = traceback_text


def script_traceback(error: BaseException) -> str:
    """The traceback of an error in a script, without the worker's own frames; empty when
    no frame is the script's (an error the worker found in what a hook returned)."""
    described = traceback.TracebackException.from_exception(error)
    frames = [frame for frame in described.stack if not frame.filename.startswith(_HERE)]
    if not frames and not isinstance(error, SyntaxError):
        return ""
    described.stack = traceback.StackSummary.from_list(frames)
    return "".join(described.format()).rstrip()


def global_name(name: str) -> str:
    """The global that holds a port or parameter (``T-INPUT`` is ``T_INPUT``)."""
    name = re.sub(r"\W", "_", name)
    return "_" + name if name[:1].isdigit() else name


class Script:
    """A script run for one module: its namespace and hooks. ``use_global_names`` makes
    the module's inputs, outputs and parameters globals of the script too."""

    def __init__(self, path: str, module: ModuleProxy, use_global_names: bool = False):
        self.path, self.file = path, os.path.basename(path)
        self.module = module
        self.namespace: dict[str, Any] = {"__name__": os.path.splitext(self.file)[0],
                                          "__file__": path, "__builtins__": __builtins__}
        for helper in LOGGING_HELPERS:
            self.namespace[helper] = getattr(module, helper)
        self.globals = self._global_names() if use_global_names else {}
        self.namespace.update(self.globals)
        try:
            with open(path, encoding="utf-8") as f:
                code = compile(f.read(), path, "exec")
            exec(code, self.namespace)
        except Exception as e:
            raise ScriptError(f"{self.file} failed to load: {type(e).__name__}: {e}",
                              script_traceback(e)) from None
        self._check_globals()
        self.hooks = {name: self._hook(name) for name in HOOKS}
        if self.hooks["tick"] is None:
            raise ScriptError(f"{self.file} defines no tick() function (a script needs "
                              f"def tick(module): or def tick():)")

    def _global_names(self) -> dict[str, Any]:
        module, found, kinds = self.module, {}, {}
        for kind, values in (("input", module.inputs), ("output", module.outputs),
                             ("parameter", module.parameters)):
            for name, value in values.items():
                key = global_name(name)
                if key in kinds:
                    raise ScriptError(f"use_global_names: the {kind} {name} and the "
                                      f"{kinds[key]} of {module.path} are both the global "
                                      f"{key} of {self.file}")
                if key in LOGGING_HELPERS:
                    raise ScriptError(f"use_global_names: the {kind} {name} of {module.path} "
                                      f"would hide the logging helper {key}() of {self.file}")
                found[key], kinds[key] = value, f"{kind} {name}"
        self._kinds = kinds
        return found

    def _check_globals(self) -> None:
        for key, value in self.globals.items():
            if self.namespace.get(key) is not value:
                raise ScriptError(f"use_global_names: {self.file} defines {key}, which is "
                                  f"also the {self._kinds[key]} of {self.module.path}; "
                                  f"rename one of them")

    def _hook(self, name: str):
        hook = self.namespace.get(name)
        if hook is None:
            return None
        if not callable(hook):
            raise ScriptError(f"{name} in {self.file} is not a function")
        try:
            signature = inspect.signature(hook)
        except (TypeError, ValueError):
            return hook, len(COMMAND_ARGUMENTS) if name == "command" else 1
        positional = [p for p in signature.parameters.values()
                      if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        required = [p for p in positional if p.default is p.empty]
        keyword_only = any(p.kind == p.KEYWORD_ONLY and p.default is p.empty
                           for p in signature.parameters.values())
        varying = any(p.kind == p.VAR_POSITIONAL for p in signature.parameters.values())
        if name == "command":
            if len(required) > len(COMMAND_ARGUMENTS) or keyword_only or \
                    (len(positional) < 2 and not varying):
                raise ScriptError(f"command() in {self.file} must take (module, name), "
                                  f"optionally followed by x, y and value, not {signature}")
            return hook, len(COMMAND_ARGUMENTS) if varying else \
                min(len(positional), len(COMMAND_ARGUMENTS))
        if len(required) > 1 or keyword_only:
            raise ScriptError(f"{name}() in {self.file} must take no argument or one (the "
                              f"module), not {signature}")
        return hook, int(bool(positional) or varying)

    def has(self, name: str) -> bool:
        return self.hooks[name] is not None

    def call(self, name: str, *details: Any) -> Any:
        """Call a hook (nothing if the script has none) with the module, if it takes it,
        and ``details`` (a command's name, x, y and value, as many as it takes); an
        exception in it is a ScriptError with the script's traceback."""
        found = self.hooks[name]
        if found is None:
            return None
        hook, arguments = found
        if self.globals:
            self._refresh_globals()
        try:
            result = hook(*(self.module, *details)[:arguments])
            if name == "tick":
                copy_returned(self.module.path, dict(self.module.outputs), result)
                self._take_rebound_outputs()
        except Exception as e:
            raise ScriptError(f"{name}() of {self.file} failed: {type(e).__name__}: {e}",
                              script_traceback(e)) from None
        return result

    def _refresh_globals(self) -> None:
        for name, value in self.module.parameters.items():
            self.namespace[global_name(name)] = value

    def _take_rebound_outputs(self) -> None:
        """An output global the tick assigned (``global OUTPUT; OUTPUT = x``) is copied
        into the output, which the global then names again."""
        for name, array in self.module.outputs.items():
            key = global_name(name)
            value = self.namespace.get(key)
            if value is not array and key in self.globals:
                try:
                    copy_returned(self.module.path, dict(self.module.outputs), {name: value})
                finally:
                    self.namespace[key] = array
