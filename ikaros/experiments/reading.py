"""Recordings as xarray Datasets: read from an HDF5 file, or kept in memory by ``net.run``."""
from __future__ import annotations

import fnmatch
import os
import warnings

import numpy as np

from ..modules.io._recordingfile import (TIME_SERIES, RecordingFile, check_time_series)
from .recording import h5py_module
from .signals import Signal


def xarray_module():
    """xarray, or an ImportError with the pip install that fixes it."""
    try:
        import xarray
    except ImportError:
        raise ImportError("recordings as Datasets need xarray: "
                          "pip install 'ikaros[record]'") from None
    return xarray


def axis_name(signal: str, axis: int) -> str:
    """The dimension name of axis ``axis`` of a recorded signal (after ``tick``)."""
    return f"{signal}.dim_{axis}"


def to_dataset(signals: list[Signal], rows: np.ndarray, ticks: np.ndarray,
               times: np.ndarray, attrs: dict, real_time: np.ndarray | None = None):
    """An xarray Dataset of one variable per signal, dimensions ``tick`` and the signal's
    own axes, with ``time`` (and ``real_time``) as coordinates along ``tick``."""
    xr = xarray_module()
    n = len(ticks)
    variables = {}
    for s in signals:
        values = rows[:n, s.start:s.stop].reshape((n,) + tuple(s.shape))
        dims = ("tick",) + tuple(axis_name(s.name, k) for k in range(len(s.shape)))
        variables[s.name] = (dims, values)
    coords = {"tick": ("tick", np.asarray(ticks, np.int64)),
              "time": ("tick", np.asarray(times, np.float64))}
    if real_time is not None:
        coords["real_time"] = ("tick", np.asarray(real_time, np.float64))
    return xr.Dataset(variables, coords=coords, attrs=attrs)


def open_file(filename: str) -> RecordingFile:
    """A recording open for reading and checked (modules/io/_recordingfile.py): a
    damaged one is refused with a RecordingError (an OSError) that names the file and the
    damage, or read up to its last whole chunk (``damage`` says so)."""
    h5py_module()
    return RecordingFile(os.path.abspath(filename))


def open_recording(filename: str, only: list[str] | str | None = None):
    """The signals of a recording (``ikaros --record`` or ``net.record``) as an xarray
    Dataset: one variable per recorded output (``ds["Arm.DISTANCE"]``), dimension ``tick``
    first. ``only`` keeps the signals matching these glob patterns. A recording still being
    written, or cut off by a crash or a full disk, is read up to its last flushed row
    (never a row that was not written).

    A damaged file (cut short, overwritten) is refused with an OSError naming the file and
    the damage, or, when only its end is missing, read up to its last whole chunk: then
    ``attrs["damage"]`` says what is missing, and a RecordingWarning says it too. Values
    that fail the file's checks are never returned.

    The attributes hold the model file's name and text (``model``), the parameters at the
    start and their changes while running (``parameter_changes``: (tick, address, value)),
    the seeds, the command line, the ikaros version, ``every`` and ``finished``."""
    with open_file(filename) as f:
        signals = [Signal(*s) for s in f.signals]
        if only is not None:
            patterns = [only] if isinstance(only, str) else list(only)
            signals = [s for s in signals
                       if any(fnmatch.fnmatchcase(s.name, p) for p in patterns)]
        n = f.rows
        if signals:
            first = min(s.start for s in signals)
            last = max(s.stop for s in signals)
            rows = f.read("data", 0, n, slice(first, last))
            signals = [Signal(s.name, s.shape, s.start - first, s.stop - first)
                       for s in signals]
        else:
            rows = np.zeros((n, 0), np.float32)
        ticks, times, real_times = (f.read(name, 0, n) for name in TIME_SERIES)
        check_time_series(f, ticks, times, real_times)
        attrs = _attributes(f)
        if f.damage:
            warnings.warn(f.damage, RecordingWarning, stacklevel=2)
            attrs["damage"] = f.damage
        return to_dataset(signals, rows, ticks, times, attrs, real_times)


class RecordingWarning(UserWarning):
    """A recording read only in part (it is damaged): the message says what is missing."""


def _attributes(f: RecordingFile) -> dict:
    h = f.header
    return {"model_file": h["model_file"], "top_group": h["top_group"], "model": f.model,
            "parameters": h["parameters"], "seeds": h["seeds"],
            "parameter_changes": f.parameter_changes(), "command_line": h["command_line"],
            "ikaros_version": h["ikaros_version"], "created": h["created"],
            "every": int(h["every"]), "tick_duration": float(h["tick_duration"]),
            "finished": bool(h["finished"])}
