"""Recording a run into one HDF5 file while it runs.

The chosen outputs of a recorded tick go into the next row of a ring of blocks in memory,
by an output tap (kernel/taps.py): with the compiled tick an instruction of the compiled
call that starts the next tick keeps the row and its tick number and moves on to the next
row, so no Python runs per tick; without it, one NumPy gather. The tap calls the recorder
back only when a block is full, and when the writer asks for the rows so far (every
``flush_seconds``); the real time of a row is read then and interpolated by tick number for
the rows in between. A full block (several HDF5 chunks) goes to a writer
thread, which byte-shuffles and compresses it without the GIL (chunks.py) and writes each
chunk as it stands, so compression never holds up the kernel. While it records, the GIL's
switch interval is short (kernel/switching.py): the writer takes the GIL back after each
compression within a fraction of a millisecond, not the 5 ms the kernel thread would
otherwise keep it, and so keeps up with a fast tick. The file is in SWMR mode:
readers may open it while the run goes on, and a run that is killed leaves a file readable
up to its last flushed chunk.

After each flush of the file the dataset ``stored`` is set to the number of rows written
and flushed, and the file flushed again: a reader reads only that many rows, so rows that a
failed write (a full disk) or a kill left half written are never read. A write that fails
ends the recording (writefaults.py says what then happens to the run).
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

from .. import priority
from ..modules.io._recordingfile import FORMAT, FORMAT_VERSION, stored_count, write_text
from ..kernel import switching
from ..kernel.taps import ROW, SIGNAL, TICK
from ..module import FATAL_ERROR, WARNING
from ..version import __version__
from .chunks import COMPRESSION_LEVEL, shuffled, shuffled_deflate
from .signals import model_text, module_parameters, seeds, select_outputs
from .writefaults import (check_on_error, failure_text, probe_room, reason,
                          remove_recording)

# HDF5 takes about 0.1 ms (holding the GIL) per chunk written and per dataset write,
# whatever its size: big chunks, written a block of them at a time, keep that small per tick
CHUNK_BYTES = 16 << 20        # at most this many bytes of values per chunk
BLOCK_BYTES = 32 << 20         # about this many per block handed to the writer
BLOCK_ROWS = 1 << 16           # and at most this many rows
RING_BLOCKS = 2                # the block being filled and the one being written
FLUSH_SECONDS = 1.0            # a partly filled chunk is written after this long
PATH_BYTES, VALUE_BYTES = 256, 4096     # room for one parameter change
PROBE_BYTES = 256 << 10        # free room needed at the start, besides the model's text
CHANGE_DTYPE = np.dtype([("tick", "<i8"), ("path", f"S{PATH_BYTES}"),
                         ("value", f"S{VALUE_BYTES}")])


def h5py_module():
    """h5py, or an ImportError with the pip install that fixes it."""
    try:
        import h5py
    except ImportError:
        raise ImportError("recording needs h5py: pip install 'ikaros[record]'") from None
    return h5py


class Recorder:
    """Records outputs of a network into an HDF5 file, every ``every``-th tick from the next
    tick on, until ``close()`` (or the network's ``close()``).

    ``only``: glob patterns of output addresses (``"Arm.*.OUTPUT"``); every output when None.
    ``flush_seconds``: how often the rows so far are written and flushed (a run killed
    with SIGKILL loses at most about this long; 0: after every tick). ``on_error``: when
    writing fails, "stop" the run (a fatal error) or "continue" it without recording (a
    warning); either way the message names the file and the ticks it holds.
    """

    def __init__(self, net, filename: str, only: list[str] | str | None = None,
                 every: int = 1, command_line: list[str] | None = None,
                 flush_seconds: float = FLUSH_SECONDS, on_error: str = "stop"):
        h5py = h5py_module()
        if int(every) < 1:
            raise ValueError(f"every must be a whole number >= 1, not {every}")
        if not float(flush_seconds) >= 0:
            raise ValueError(f"flush_seconds must be a number >= 0, not {flush_seconds}")
        self.on_error = check_on_error(on_error)
        self.net = net
        self.filename = os.path.abspath(filename)
        self.every = int(every)
        self.signals, self._index = select_outputs(net, only)
        columns = self._index.size
        row_bytes = 4 * max(columns, 1)
        self.chunk_ticks = T = max(1, min(16384, CHUNK_BYTES // row_bytes))
        self._block_rows = T * max(1, min(BLOCK_BYTES // (T * row_bytes), BLOCK_ROWS // T))
        self.flush_seconds = float(flush_seconds)
        self._create_file(h5py, command_line, columns)
        shuffled(np.zeros((1, 1), np.float32))      # numba's start, before the run goes on
        # rows past the last filled one of a block are never read, so need no clearing;
        # its pages are touched here, not by the kernel thread's copies
        self._ring = np.empty((RING_BLOCKS * self._block_rows, columns), np.float32)
        self._ring.fill(0)
        self._real = np.zeros(len(self._ring))       # the real_time of each row
        self._free: queue.SimpleQueue = queue.SimpleQueue()    # blocks free to fill
        for block in range(RING_BLOCKS):
            self._free.put(block)
        self._row = 0                   # the row of the file of the block's first row
        self._closed = False
        self._tap = net.add_tap(self._index, self._ring, self.every, self._signalled)
        self._start_block()
        if flush_seconds <= 0:
            self._tap.request()
        # real times are read when the tap calls back, and rows between two readings get
        # times interpolated by tick: (tick, its real_time) of the last reading
        self._anchor = (net.tick - 1, net.clock.real_time)
        self._real_zero: float | None = None     # real_time of the first row written
        self._file_flushed = time.perf_counter()
        self._queue: queue.Queue = queue.Queue()
        self._error: BaseException | None = None      # set by the writer thread
        self._reported = False
        # rows written (the file's row count, the tick of its last row), and those of them
        # flushed and counted in "stored": all a reader reads
        self._written = (0, None)
        self.stored = 0
        self._first_tick: int | None = None
        self._last_tick: int | None = None
        self._writer = threading.Thread(target=self._write_loop, name="ikaros-recorder",
                                        daemon=True)
        self._writer.start()
        switching.shorten()     # the writer gets the GIL back soon after each compression
        net.parameter_hooks.append(self.parameter_changed)
        net.close_hooks.append(self._close_with_network)
        atexit.register(self.close)     # a script that ends without close() loses nothing

    def _create_file(self, h5py, command_line, columns: int) -> None:
        """The file with its header and empty datasets, flushed; nothing is left behind
        when it cannot be written (a disk full already)."""
        try:
            probe_room(self.filename, PROBE_BYTES + len(model_text(self.net)))
            self._file = h5py.File(self.filename, "w", libver="latest")
        except OSError as e:
            remove_recording(self.filename, only_empty=True)
            raise OSError(f"cannot write the recording {self.filename}: {reason(e)}") \
                from None
        try:
            self._write_header(command_line)
            self._create_datasets(columns)
            self._file.swmr_mode = True       # from here on readers may open it
            self._file.flush()
        except Exception as e:      # noqa: BLE001: the file is removed, the error told
            _detach(self._file)
            self._data = self._times = self._stored = self._changes = None
            try:
                self._file.close()
            except Exception:       # noqa: BLE001: it goes anyway
                pass
            remove_recording(self.filename)
            raise OSError(f"cannot write the recording {self.filename}: {reason(e)}") \
                from None

    def _write_header(self, command_line: list[str] | None) -> None:
        """The attributes (numbers, and the format's name) and the header's text (JSON)
        and the model's, as datasets with checksums."""
        net, f = self.net, self._file
        parameters = module_parameters(net)
        f.attrs.update({"format": np.bytes_(FORMAT), "format_version": FORMAT_VERSION,
                        "every": self.every, "tick_duration": net.clock.tick_duration,
                        "first_tick": net.tick, "finished": False,
                        # set when closed: in place, the file's end is not rewritten
                        "ticks_recorded": 0})
        write_text(f, "header", json.dumps({
            "ikaros_version": __version__, "model_file": net.filename or "",
            "top_group": net.top.name,
            "command_line": command_line if command_line is not None else sys.argv,
            "created": datetime.now(timezone.utc).isoformat(timespec="seconds"),
            "signals": [[s.name, list(s.shape), s.start, s.stop] for s in self.signals],
            "parameters": parameters, "seeds": seeds(parameters)}))
        write_text(f, "model", model_text(net))

    def _create_datasets(self, columns: int) -> None:
        f, T = self._file, self.chunk_ticks
        self._data = f.create_dataset(
            "data", (0, columns), maxshape=(None, max(columns, 1)), dtype="<f4",
            chunks=(T, max(columns, 1)), compression="gzip",
            compression_opts=COMPRESSION_LEVEL, shuffle=True)
        self._times = {name: f.create_dataset(name, (0,), maxshape=(None,), dtype=dtype,
                                              chunks=(T,), fletcher32=True)
                       for name, dtype in (("tick", "<i8"), ("time", "<f8"),
                                           ("real_time", "<f8"))}
        self._changes = f.create_dataset("parameter_changes", (0,), maxshape=(None,),
                                         dtype=CHANGE_DTYPE, chunks=(16,),
                                         compression="gzip")
        self._stored = f.create_dataset("stored", data=stored_count(0))

    # --- the kernel thread ---------------------------------------------------------------
    def _start_block(self) -> None:
        """Start filling a free block of the ring (waiting for the writer when none is)."""
        self._block = self._free.get()
        self._first = self._block * self._block_rows       # its first row in the ring
        self._sent = 0                  # rows of it already handed over in whole chunks
        self._timed = self._first       # the ring row up to which real times are set
        self._tap.give(self._first, self._first + self._block_rows)

    def _signalled(self) -> None:
        """The tap's call back (at the start of a tick): the block is full, or the writer
        asked for the rows so far (about once a second)."""
        tap = self._tap
        if self._error is not None:
            tap.stop()
            self._report()
            return
        tap.state[SIGNAL] = self.flush_seconds <= 0     # (0: hand over after every tick)
        self._hand_over()

    def _time_rows(self) -> None:
        """The real times of the rows kept since the last reading: now's reading (the start
        of the tick just done) for that tick, interpolated by tick for the others."""
        net = self.net
        row = int(self._tap.state[ROW])
        tick, now = net.tick - 1, net.clock.real_time
        if row > self._timed:
            ticks = self._tap.ticks[self._timed:row]
            last_tick, last = self._anchor
            if tick > last_tick:
                self._real[self._timed:row] = last + (ticks - last_tick) * (
                    (now - last) / (tick - last_tick))
            else:
                self._real[self._timed:row] = now
            self._timed = row
        self._anchor = (tick, now)

    def _hand_over(self) -> None:
        """Give the writer the block when full, else a copy of its rows not yet written in
        whole chunks (they are written, and rewritten once the block is full)."""
        self._time_rows()
        T, sent, first = self.chunk_ticks, self._sent, self._first
        n = int(self._tap.state[ROW]) - first
        ring = self._ring[first:first + self._block_rows]
        ticks = self._tap.ticks[first:first + n]
        real = self._real[first:first + n]
        if n == self._block_rows:
            self._put(("rows", self._row + sent, ring[sent:], ticks[sent:], real[sent:],
                       self._block))
            self._row += n
            self._start_block()
        elif n > sent:
            whole = -(-n // T) * T        # to the end of the chunk the last row is in
            self._put(("rows", self._row + sent, ring[sent:whole].copy(), ticks[sent:],
                       real[sent:], None))
            self._sent = n - n % T

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
        """Tell the network once that writing failed: a fatal error that ends the run, or
        with on_error="continue" a warning."""
        if not self._reported:
            self._reported = True
            self.net.notify(WARNING if self.on_error == "continue" else FATAL_ERROR, None,
                            self.failure)

    @property
    def failure(self) -> str | None:
        """Why writing failed and what the file holds (None while it has not failed)."""
        if self._error is None:
            return None
        return failure_text(self.filename, self._error, self.stored, self._first_tick,
                            self._last_tick, self.on_error)

    @property
    def closed(self) -> bool:
        """Whether the recording has been closed (``failure`` says whether writing it
        failed before)."""
        return self._closed

    def _close_with_network(self) -> None:
        """When the network closes (a failure is reported in its log, never raised)."""
        self.close()

    def close(self, complete: bool = True) -> None:
        """Write what is left, mark the recording finished (unless not ``complete``: an
        interrupted run) and close the file. Call it between ticks (from the kernel's
        thread while the network runs). A write that fails is reported in the network's
        log (see ``on_error``) and in ``failure``; the file then keeps the rows written
        before and stays not finished."""
        if self._closed:
            return
        self._closed = True
        atexit.unregister(self.close)
        net = self.net
        for hooks, hook in ((net.parameter_hooks, self.parameter_changed),
                            (net.close_hooks, self._close_with_network)):
            if hook in hooks:
                hooks.remove(hook)
        if self._error is None:
            if self._tap.state[TICK] < net.tick:    # not a tick cut off (Ctrl-C) half done
                self._tap.settle()          # the row of the tick just done
            self._hand_over()
        net.remove_tap(self._tap)
        self._queue.put(None)
        self._writer.join()
        switching.restore()
        self._data = self._times = self._stored = self._changes = None     # before the file
        try:
            self._file.close()
        except Exception as e:      # noqa: BLE001: reported below
            self._error = self._error or e
        if self._error is None:
            try:
                # without HDF5's lock: a reader in another process that has the file
                # open (as SWMR lets it) holds it, and the file would stay not finished
                with h5py_module().File(self.filename, "a", locking=False) as f:
                    f.attrs.modify("finished", complete)      # (in place)
                    f.attrs.modify("ticks_recorded", self.stored)
            except Exception as e:      # noqa: BLE001: reported below
                self._error = e
        if self._error is not None:     # what was flushed stays readable, not "finished"
            if self.stored == 0:
                remove_recording(self.filename)
            self._report()

    def __enter__(self):
        return self

    def __exit__(self, kind, error, trace):
        self.close(complete=not isinstance(error, KeyboardInterrupt))

    # --- the writer thread ---------------------------------------------------------------
    def _write_loop(self) -> None:
        """Write what the kernel thread hands over; ask it for the rows of a partly filled
        block every ``flush_seconds``."""
        priority.background_thread()
        every = self.flush_seconds
        due = time.perf_counter() + every
        while True:
            try:
                item = self._queue.get(timeout=max(due - time.perf_counter(), 0)
                                       if every > 0 else None)
            except queue.Empty:
                item = ()
            if every > 0 and time.perf_counter() >= due:
                self._tap.request()
                due = time.perf_counter() + every
            if not item:
                if item is None:
                    self._commit_last()
                    return
                continue
            try:
                if self._error is None:
                    if item[0] == "rows":
                        self._write_rows(*item[1:5], flush=item[5] is None)
                    else:
                        self._write_change(*item[1:])
            except Exception as e:      # reported to the kernel thread at its next call back
                self._fail(e)
            finally:
                if item[0] == "rows" and item[5] is not None:
                    self._free.put(item[5])     # the kernel thread may fill it again

    def _write_rows(self, start: int, rows: np.ndarray, ticks: np.ndarray,
                    real: np.ndarray, flush: bool) -> None:
        """Write ``len(ticks)`` rows from the file's row ``start`` (the first of a chunk);
        ``rows`` holds whole chunks. The file is flushed every ``flush_seconds``, and with
        ``flush`` (a partly filled block)."""
        T, n = self.chunk_ticks, len(ticks)
        end = start + n
        payloads = shuffled_deflate(rows[:-(-n // T) * T], T)
        if end > self._data.shape[0]:
            self._data.resize(end, axis=0)
            for dataset in self._times.values():
                dataset.resize(end, axis=0)
        if rows.shape[1]:
            for j, payload in enumerate(payloads):
                self._data.id.write_direct_chunk((start + j * T, 0), payload)
        ticks = np.asarray(ticks, np.int64)
        self._times["tick"][start:end] = ticks
        self._times["time"][start:end] = ticks * self.net.clock.tick_duration
        if self._real_zero is None and len(real):
            self._real_zero = real[0]
        self._times["real_time"][start:end] = np.array(real) - (self._real_zero or 0.0)
        if n:
            if self._first_tick is None and start == 0:
                self._first_tick = int(ticks[0])
            self._written = (end, int(ticks[-1]))
        if flush or time.perf_counter() - self._file_flushed > self.flush_seconds:
            self._commit()

    def _commit(self) -> None:
        """Flush the rows written, then count them in ``stored`` (flushed again): the
        count never covers a row that is not in the file."""
        end, last_tick = self._written
        self._file.flush()
        if end > self.stored:
            self._stored[:] = stored_count(end)
            self._file.flush()
            self.stored, self._last_tick = end, last_tick
        self._file_flushed = time.perf_counter()

    def _commit_last(self) -> None:
        """At the end: count the rows written since the last flush."""
        if self._error is None and self._written[0] > self.stored:
            try:
                self._commit()
            except Exception as e:      # noqa: BLE001: reported by close()
                self._fail(e)

    def _fail(self, error: BaseException) -> None:
        """Writing failed: nothing more goes into the file (it keeps the rows counted in
        ``stored``; one that holds none is removed now, not at close); the kernel thread
        hears of it at its next call back."""
        _detach(self._file)
        if self.stored == 0:
            remove_recording(self.filename)
        self._error = error
        self._tap.request()

    def _write_change(self, tick: int, path: str, value: str) -> None:
        k = self._changes.shape[0]
        self._changes.resize(k + 1, axis=0)
        self._changes[k] = (tick, path.encode()[:PATH_BYTES], value.encode()[:VALUE_BYTES])


def _detach(file) -> None:
    """Point the HDF5 file's descriptor at the null device: after a failed write HDF5
    tries to write its caches again at every close, failing each time, and a process that
    ends with such objects left can crash; written to the null device they close
    cleanly, and the file on disk stays as it was after its last good flush."""
    try:
        fd = file.id.get_vfd_handle()
        null = os.open(os.devnull, os.O_RDWR)
    except Exception:       # noqa: BLE001: not a file on disk (nothing to protect)
        return
    try:
        os.dup2(null, fd)
    finally:
        os.close(null)
