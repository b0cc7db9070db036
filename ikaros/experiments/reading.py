"""Recordings as xarray Datasets: read from an HDF5 file, or kept in memory by ``net.run``."""
from __future__ import annotations

import fnmatch
import json

import numpy as np

from .recording import FORMAT, h5py_module
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


def _open(h5py, filename: str):
    """Open a recording, also one still being written or cut off (SWMR)."""
    try:
        return h5py.File(filename, "r")
    except OSError as first:
        try:
            return h5py.File(filename, "r", swmr=True)
        except OSError:
            raise OSError(f"cannot read the recording {filename}: {first}") from None


def readable_rows(f) -> int:
    """The rows of an open recording file that were written whole: up to its ``stored``
    count (rows past it may be half written, by a full disk or a kill; a file of format
    version 1 has no count)."""
    n = min(f["tick"].shape[0], f["time"].shape[0], f["real_time"].shape[0],
            f["data"].shape[0])
    return min(n, int(f["stored"][0])) if "stored" in f else n


def open_recording(filename: str, only: list[str] | str | None = None):
    """The signals of a recording (``ikaros --record`` or ``net.record``) as an xarray
    Dataset: one variable per recorded output (``ds["Arm.DISTANCE"]``), dimension ``tick``
    first. ``only`` keeps the signals matching these glob patterns. A recording still being
    written, or cut off by a crash or a full disk, is read up to its last flushed row
    (never a row that was not written).

    The attributes hold the model file's name and text (``model``), the parameters at the
    start and their changes while running (``parameter_changes``: (tick, address, value)),
    the seeds, the command line, the ikaros version, ``every`` and ``finished``."""
    h5py = h5py_module()
    with _open(h5py, filename) as f:
        if f.attrs.get("format") != FORMAT:
            raise ValueError(f"{filename} is not an ikaros recording")
        signals = [Signal(name, tuple(shape), start, stop)
                   for name, shape, start, stop in json.loads(f.attrs["signals"])]
        if only is not None:
            patterns = [only] if isinstance(only, str) else list(only)
            signals = [s for s in signals
                       if any(fnmatch.fnmatchcase(s.name, p) for p in patterns)]
        n = readable_rows(f)
        if signals:
            first = min(s.start for s in signals)
            last = max(s.stop for s in signals)
            rows = f["data"][:n, first:last]
            signals = [Signal(s.name, s.shape, s.start - first, s.stop - first)
                       for s in signals]
        else:
            rows = np.zeros((n, 0), np.float32)
        attrs = _attributes(f)
        return to_dataset(signals, rows, f["tick"][:n], f["time"][:n], attrs,
                          f["real_time"][:n])


def _attributes(f) -> dict:
    a = f.attrs
    model = f["model"][()]
    changes = [(int(c["tick"]), c["path"].decode(), c["value"].decode())
               for c in f["parameter_changes"][:]]
    return {"model_file": str(a["model_file"]), "top_group": str(a["top_group"]),
            "model": model.decode() if isinstance(model, bytes) else str(model),
            "parameters": json.loads(a["parameters"]), "seeds": json.loads(a["seeds"]),
            "parameter_changes": changes,
            "command_line": json.loads(a["command_line"]),
            "ikaros_version": str(a["ikaros_version"]), "created": str(a["created"]),
            "every": int(a["every"]), "tick_duration": float(a["tick_duration"]),
            "finished": bool(a["finished"])}
