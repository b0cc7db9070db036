"""What a script sees of its module: the ``module`` argument of its hooks.

Run in the worker process: it needs only the standard library and NumPy.
"""
from __future__ import annotations

from types import MappingProxyType
from typing import Any, Callable

import numpy as np

# levels of the log messages a script sends (the kernel maps them to its own)
LOG, WARNING, ERROR, DEBUG = "print", "warning", "error", "debug"


class ModuleProxy:
    """A script's view of its module.

    ``inputs`` maps input names to read-only NumPy arrays (None for an unconnected optional
    input), ``outputs`` output names to float32 arrays the script writes in place, and
    ``parameters`` parameter names to their values (a number, bool, string or array, as the
    class file's types say; they change when the model's parameters change). Ports and
    parameters are attributes too (``module.INPUT``, ``module.gain``). ``tick`` is the
    current tick (-1 in ``init``); ``name`` and ``path`` name the module.
    """

    def __init__(self, name: str, path: str, inputs: dict[str, np.ndarray | None],
                 outputs: dict[str, np.ndarray], parameters: dict[str, Any],
                 send_log: Callable[[str, str], None]):
        self.name, self.path = name, path
        self.tick = -1
        self._inputs = {k: _read_only(v) for k, v in inputs.items()}
        self.inputs = MappingProxyType(self._inputs)
        self._outputs = dict(outputs)
        self.outputs = MappingProxyType(self._outputs)
        self._parameters = dict(parameters)
        self.parameters = MappingProxyType(self._parameters)
        self._send_log = send_log

    def __getattr__(self, name: str) -> Any:
        # only called for names that are not attributes of the proxy itself
        for table in ("_inputs", "_outputs", "_parameters"):
            values = self.__dict__.get(table, {})
            if name in values:
                return values[name]
        raise AttributeError(f"module {self.__dict__.get('path', '?')} has no input, output "
                             f"or parameter named {name!r}")

    def log(self, message: Any) -> None:
        """A message in the Ikaros log (print level)."""
        self._send_log(LOG, str(message))

    def warning(self, message: Any) -> None:
        self._send_log(WARNING, str(message))

    def error(self, message: Any) -> None:
        """An error in the log; the run goes on."""
        self._send_log(ERROR, str(message))

    def debug(self, message: Any) -> None:
        """A debug message (shown when the log level is debug)."""
        self._send_log(DEBUG, str(message))

    def set_parameters(self, values: dict[str, Any]) -> None:
        """New parameter values from the kernel (before a tick)."""
        self._parameters.update(values)


def _read_only(array: np.ndarray | None) -> np.ndarray | None:
    if array is None:
        return None
    view = array.view()
    view.flags.writeable = False
    return view


def copy_returned(path: str, outputs: dict[str, np.ndarray], returned: Any) -> None:
    """Copy what ``tick`` returned ({output name: array-like}) into the outputs. A name
    that is no output, or a value whose shape is not the output's (a single number fills
    the output), is a ValueError naming the module, output and shapes."""
    if returned is None:
        return
    if not isinstance(returned, dict):
        raise TypeError(f"tick() of {path} returned a {type(returned).__name__}; it may "
                        f"return None or a dict {{output name: values}}")
    for name, value in returned.items():
        target = outputs.get(name)
        if target is None:
            raise ValueError(f"tick() of {path} returned a value for {name!r}, which is not "
                             f"an output (outputs: {', '.join(outputs) or 'none'})")
        value = np.asarray(value, dtype=np.float32)
        if value.shape != target.shape and value.shape != ():
            raise ValueError(f"tick() of {path} returned shape {value.shape} for output "
                             f"{name}, which has shape {target.shape}")
        np.copyto(target, value)
