"""Recording a run into one HDF5 file while it runs.

The kernel thread copies the chosen outputs into a block of rows (one NumPy gather per
recorded tick). A full block is one HDF5 chunk: a writer thread compresses it (byte
shuffle and zlib, which run without the GIL) and writes it as it stands, so compression
never holds up the kernel. The file is in SWMR mode: readers may open it while the run goes
on, and a run that is killed leaves a file readable up to its last flushed chunk.
"""
from __future__ import annotations

import atexit
import json
import os
import queue
import sys
import threading
import time
from datetime import datetime, timezone

import numpy as np

from ..module import WARNING
from .signals import module_parameters, seeds, select_outputs

FORMAT = "ikaros-recording"
FORMAT_VERSION = 1
CHUNK_BYTES = 1 << 20          # at most this many bytes of values per chunk
FLUSH_SECONDS = 1.0            # a partly filled chunk is written after this long
PATH_BYTES, VALUE_BYTES = 256, 4096     # room for one parameter change
CHANGE_DTYPE = np.dtype([("tick", "<i8"), ("path", f"S{PATH_BYTES}"),
                         ("value", f"S{VALUE_BYTES}")])
COMPRESSION_LEVEL = 1


def h5py_module():
    """h5py, or an ImportError with the pip install that fixes it."""
    try:
        import h5py
    except ImportError:
        raise ImportError("recording needs h5py: pip install 'ikaros[record]'") from None
    return h5py


try:        # ISA-L's deflate writes the same format as zlib, about 8 times as fast
    from isal.isal_zlib import compress as _deflate
except ImportError:
    from zlib import compress as _deflate


def _shuffled_deflate(rows: np.ndarray) -> bytes:
    """A chunk as HDF5's shuffle and deflate filters would store it."""
    shuffled = np.ascontiguousarray(rows.view(np.uint8).reshape(-1, rows.itemsize).T)
    return _deflate(shuffled, COMPRESSION_LEVEL)


class Recorder:
    """Records outputs of a network into an HDF5 file, every ``every``-th tick from the next
    tick on, until ``close()`` (or the network's ``close()``).

    ``only``: glob patterns of output addresses (``"Arm.*.OUTPUT"``); every output when None.
    """

    def __init__(self, net, filename: str, only: list[str] | str | None = None,
                 every: int = 1, command_line: list[str] | None = None,
                 flush_seconds: float = FLUSH_SECONDS):
        h5py = h5py_module()
        if int(every) < 1:
            raise ValueError(f"every must be a whole number >= 1, not {every}")
        self.net = net
        self.filename = os.path.abspath(filename)
        self.every = int(every)
        self.signals, self._index = select_outputs(net, only)
        columns = self._index.size
        self.chunk_ticks = max(1, min(16384, CHUNK_BYTES // (4 * max(columns, 1))))
        self.flush_seconds = flush_seconds
        try:
            self._file = h5py.File(self.filename, "w", libver="latest")
        except OSError as e:
            reason = os.strerror(e.errno) if e.errno else str(e)
            raise OSError(f"cannot write the recording {filename}: {reason}") from None
        self._write_header(command_line)
        self._create_datasets(columns)
        self._file.swmr_mode = True       # from here on readers may open it
        self._file.flush()
        self._copy_row = self._row_copier(net.arena.block)
        self._free: queue.SimpleQueue = queue.SimpleQueue()    # row blocks written, to reuse
        self._start_rows()
        self._chunk = 0                 # the chunk being filled
        self._last_flush = time.perf_counter()     # last hand-over of a partial chunk
        self._started = self._last_flush
        self._file_flushed = self._last_flush
        self._queue: queue.Queue = queue.Queue(maxsize=4)
        self._error: BaseException | None = None      # set by the writer thread
        self._reported = False
        self._writer = threading.Thread(target=self._write_loop, name="ikaros-recorder",
                                        daemon=True)
        self._writer.start()
        self._closed = False
        self._next = net.tick           # the next tick to record
        hooks = net.controller.tick_hooks
        # a recording ended by the web UI's rebuild left its hook here: drop it
        hooks[:] = [h for h in hooks if not (isinstance(getattr(h, "__self__", None),
                                                        Recorder) and h.__self__.closed)]
        hooks.append(self.hook)
        net.parameter_hooks.append(self.parameter_changed)
        net.close_hooks.append(self._close_with_network)
        atexit.register(self.close)     # a script that ends without close() loses nothing

    def _write_header(self, command_line: list[str] | None) -> None:
        net, f = self.net, self._file
        parameters = module_parameters(net)
        f.attrs.update({
            "format": FORMAT, "format_version": FORMAT_VERSION,
            "ikaros_version": _version(), "model_file": net.filename or "",
            "top_group": net.top.name,
            "command_line": json.dumps(command_line if command_line is not None
                                       else sys.argv),
            "created": datetime.now(timezone.utc).isoformat(timespec="seconds"),
            "every": self.every, "tick_duration": net.clock.tick_duration,
            "first_tick": net.tick,
            "signals": json.dumps([[s.name, list(s.shape), s.start, s.stop]
                                   for s in self.signals]),
            "parameters": json.dumps(parameters), "seeds": json.dumps(seeds(parameters)),
            "finished": False,
        })
        f.create_dataset("model", data=_model_text(net))

    def _create_datasets(self, columns: int) -> None:
        f, T = self._file, self.chunk_ticks
        self._data = f.create_dataset(
            "data", (0, columns), maxshape=(None, max(columns, 1)), dtype="<f4",
            chunks=(T, max(columns, 1)), compression="gzip",
            compression_opts=COMPRESSION_LEVEL, shuffle=True)
        self._times = {name: f.create_dataset(name, (0,), maxshape=(None,), dtype=dtype,
                                              chunks=(T,))
                       for name, dtype in (("tick", "<i8"), ("time", "<f8"),
                                           ("real_time", "<f8"))}
        self._changes = f.create_dataset("parameter_changes", (0,), maxshape=(None,),
                                         dtype=CHANGE_DTYPE, chunks=(16,),
                                         compression="gzip")

    # --- the kernel thread ---------------------------------------------------------------
    def _row_copier(self, block: np.ndarray):
        """What the kernel thread does per recorded tick. When the recorded values lie
        close together in the arena, it copies the span that holds them (one memcpy) and
        the writer thread picks the columns out of a whole chunk; otherwise it gathers."""
        index = self._index
        first, last = (int(index.min()), int(index.max()) + 1) if index.size else (0, 0)
        if last - first <= 4 * index.size + 1024:
            self._width, self._columns = last - first, index - first
            span = block[first:last]
            return lambda row: np.copyto(row, span)
        self._width, self._columns = index.size, None
        return lambda row: np.take(block, index, out=row)

    def _start_rows(self) -> None:
        T = self.chunk_ticks
        try:        # rows past the last filled one are never read, so need no clearing
            self._rows = self._free.get_nowait()
        except queue.Empty:
            self._rows = np.zeros((T, self._width), np.float32)
        self._ticks = np.zeros(T, np.int64)
        self._real = np.zeros(T, np.float64)
        self._n = 0

    def hook(self) -> None:
        """After every tick: keep the outputs of the tick just done when it is due."""
        net = self.net
        tick = net.tick - 1
        if tick < self._next or self._closed:
            return
        if self._error is not None:
            self._report()
            return
        self._next = tick + self.every
        n = self._n
        self._copy_row(self._rows[n])
        self._ticks[n] = tick
        self._real[n] = now = time.perf_counter()
        self._n = n = n + 1
        if n == self.chunk_ticks:
            self._hand_over(full=True)
        elif now - self._last_flush > self.flush_seconds:
            self._hand_over(full=False)

    def _hand_over(self, full: bool) -> None:
        n = self._n
        rows, ticks, real = self._rows, self._ticks[:n], self._real[:n]
        if not full:
            rows, ticks, real = rows.copy(), ticks.copy(), real.copy()
        self._put(("rows", self._chunk, rows, n, ticks, real))
        self._last_flush = time.perf_counter()
        if full:
            self._chunk += 1
            self._start_rows()

    def parameter_changed(self, path: str, value: str) -> None:
        """Keep a parameter change with the tick from which it takes effect."""
        self._put(("change", self.net.tick, path, value))

    def _put(self, item) -> None:
        """Hand an item to the writer; once writing has failed, the recording stops (with
        a warning in the network's log) and the run goes on."""
        if self._error is None:
            self._queue.put(item)
        else:
            self._report()

    def _report(self) -> None:
        if not self._reported:
            self._reported = True
            self.net.notify(WARNING, None, f"the recording {self.filename} stopped: "
                                           f"writing failed: {self._error}")

    @property
    def closed(self) -> bool:
        """Whether the recording has ended."""
        return self._closed

    def _close_with_network(self) -> None:
        """When the network closes: never raise there (its modules must still be
        stopped); a failure is a warning in the network's log."""
        try:
            self.close()
        except Exception as e:      # noqa: BLE001
            if not self._reported:
                self.net.notify(WARNING, None, f"the recording {self.filename} failed: {e}")

    def close(self) -> None:
        """Write what is left, mark the recording finished and close the file."""
        if self._closed:
            return
        self._closed = True
        atexit.unregister(self.close)
        net = self.net
        for hooks, hook in ((net.controller.tick_hooks, self.hook),
                            (net.parameter_hooks, self.parameter_changed),
                            (net.close_hooks, self._close_with_network)):
            if hook in hooks:
                hooks.remove(hook)
        if self._n and self._error is None:
            self._hand_over(full=False)
        self._queue.put(None)
        self._writer.join()
        self._file.close()
        if self._error is not None:     # what was flushed stays readable, not "finished"
            raise OSError(f"writing the recording {self.filename} failed: {self._error}")
        with h5py_module().File(self.filename, "a") as f:
            f.attrs["finished"] = True
            f.attrs["ticks_recorded"] = f["tick"].shape[0]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # --- the writer thread ---------------------------------------------------------------
    def _write_loop(self) -> None:
        while True:
            item = self._queue.get()
            if item is None:
                return
            if self._error is not None:
                continue
            try:
                if item[0] == "rows":
                    self._write_rows(*item[1:])
                else:
                    self._write_change(*item[1:])
            except Exception as e:      # reported to the kernel thread at its next hand-over
                self._error = e

    def _write_rows(self, chunk: int, rows: np.ndarray, n: int, ticks, real) -> None:
        start = chunk * self.chunk_ticks
        end = start + n
        block = rows
        if self._columns is not None:
            rows = np.take(rows, self._columns, axis=1)
        payload = _shuffled_deflate(rows)
        if n == self.chunk_ticks:
            self._free.put(block)     # always a whole chunk; rows past n are 0
        if end > self._data.shape[0]:
            self._data.resize(end, axis=0)
            for dataset in self._times.values():
                dataset.resize(end, axis=0)
        if rows.shape[1]:
            self._data.id.write_direct_chunk((start, 0), payload)
        self._times["tick"][start:end] = ticks
        self._times["time"][start:end] = ticks * self.net.clock.tick_duration
        self._times["real_time"][start:end] = real - self._started
        now = time.perf_counter()
        if now - self._file_flushed > self.flush_seconds or n < self.chunk_ticks:
            self._file.flush()
            self._file_flushed = now

    def _write_change(self, tick: int, path: str, value: str) -> None:
        k = self._changes.shape[0]
        self._changes.resize(k + 1, axis=0)
        self._changes[k] = (tick, path.encode()[:PATH_BYTES], value.encode()[:VALUE_BYTES])


def _model_text(net) -> str:
    try:
        with open(net.filename, encoding="utf-8") as f:
            return f.read()
    except (OSError, TypeError, UnicodeDecodeError):
        from ..language.writer import to_text
        return to_text(net.model)


def _version() -> str:
    from .. import __version__
    return __version__
