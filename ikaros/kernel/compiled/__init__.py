"""The compiled tick: standard element-wise and small-array modules, and the zero-delay
copies between them, run as instructions of one function compiled with numba (the
optional extra ``ikaros[fast]``), one call per stretch of compiled modules per tick.

Whether a model uses it: the top group's ``compiled`` attribute (or ``ikaros.load(path,
compiled=...)``) is ``auto`` (the default: when numba is installed and at least
``AUTO_MINIMUM`` modules can be compiled; the network starts on the NumPy plan and takes
the compiled one at a tick boundary once a background thread has started numba and made it,
see ``background.py``), ``yes`` (whenever numba is installed, from the first tick: the load
waits for numba) or ``no``. The environment variable ``IKAROS_COMPILED=0`` turns it off for
every model; ``IKAROS_COMPILED=1`` turns it on, from the first tick, for every model that does
not say ``no``.
"""
from __future__ import annotations

import os

AUTO_MINIMUM = 64          # compilable modules that make ``auto`` use the compiled tick

_OFF = ("0", "no", "false", "off")
_ON = ("1", "yes", "true", "on")


class SettingError(ValueError):
    pass


def minimum_modules(attribute: str | None) -> int | None:
    """How many compilable modules a model needs to use the compiled tick (None: never),
    from the top group's ``compiled`` attribute and the environment. ``AUTO_MINIMUM`` means
    ``auto``, whose compiled plan is made in the background."""
    text = (attribute or "").strip().lower()
    if text not in _OFF + _ON + ("", "auto"):
        raise SettingError(f'compiled="{attribute}" must be auto, yes or no')
    env = os.environ.get("IKAROS_COMPILED", "").strip().lower()
    if env in _OFF or text in _OFF:
        return None
    if text in _ON or env in _ON:
        return 1
    return AUTO_MINIMUM


_executor: list = []


def executor():
    """The compiled function (compiled once, then loaded from numba's cache), or None when
    numba is not installed or cannot compile it here."""
    if not _executor:
        try:
            from .kernel import execute
            _warm_up(execute)
        except Exception:            # not installed, or no compiler / cache folder here
            execute = None
        _executor.append(execute)
    return _executor[0]


def _warm_up(execute) -> None:
    import numpy as np
    block = np.zeros(1, dtype=np.float32)
    execute(block, np.zeros((0, 6), dtype=np.int64), 0, 0, block, np.zeros(1, np.int64),
            np.zeros(1, np.int64))
