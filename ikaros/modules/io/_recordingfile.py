"""An ikaros recording (HDF5) opened for reading and checked against itself: what the file
says it holds (its size, its count of rows written whole, its checksums) against what it
holds. Shared by the Replay module and ``ikaros.experiments``
(``open_recording``, ``ikaros --replay``).

A damaged file is refused at once with one line naming it and the damage, or, when it is
cut off, read up to its last whole chunk with a note that says so (``damage``). HDF5's own
checks catch the rest when values are read: the checksums of its metadata, the Adler-32
of each compressed chunk (the values; in format 3 also the model's text and the header's
JSON text, kept in datasets rather than in HDF5's unchecked variable-length strings), and
(format 3) Fletcher-32 on the tick and time datasets; the count of rows is kept with its
complement beside it, and a finished recording also keeps it in the checked attribute
``ticks_recorded``.
Format 1 and 2 files are checked as far as they can be (_legacyrecording.py).

A file that is being written, or whose writer was killed, is marked so in its superblock
and can only be opened for SWMR reading; a file cut off can only be read that way too
(HDF5's plain open refuses a file shorter than it should be). For SWMR reading HDF5 retries
a metadata read that fails its checksum 100 times with growing sleeps (minutes on a
damaged file, with Ctrl-C unheard, as the main thread never leaves HDF5); here it retries
``READ_ATTEMPTS`` times, a few milliseconds (``H5Pset_metadata_read_attempts``). A file
marked as being written that fails a check is looked at again for up to SETTLE_SECONDS
(its writer may be in the middle of a flush) before the failure is told.
"""
import ctypes
import json
import os
import struct
import time

import numpy as np

from ._legacyrecording import header as legacy_header, heap_damage, text_length_damage

FORMAT = "ikaros-recording"
FORMAT_VERSION = 3      # 2: "stored" counts the rows written whole; 3: checksums
TIME_SERIES = ("tick", "time", "real_time")
NUMBERS = ("every", "tick_duration", "first_tick", "finished")     # attributes
READ_ATTEMPTS = 20      # about 5 ms of retries in all (HDF5's default of 100: minutes)
SETTLE_SECONDS = 0.5    # a file being written may fail its checks while its writer flushes
SIGNATURE = b"\x89HDF\r\n\x1a\n"
SWMR_WRITING = 0x04     # superblock flag: open for SWMR writing (or its writer killed)
WRITING = 0x01          # open for writing


class RecordingError(OSError):
    """A recording that cannot be read: the message names the file and why."""


class NotARecording(ValueError):
    """An HDF5 file that is not an ikaros recording."""


def stored_count(rows: int) -> np.ndarray:
    """What the dataset "stored" holds (format 3): the count of rows written whole, then
    its bitwise complement, so that damage to it (zeros, noise) is seen: a checksum filter
    would have every flush rewrite a chunk, which costs a fast flush much."""
    return np.array([rows, ~rows], np.int64)


def write_text(f, name: str, text: str) -> None:
    """Text as UTF-8 bytes in a deflated dataset, whose stream's Adler-32 HDF5 checks as it
    reads (a variable-length string has no checksum, and a damaged one can hang HDF5; a
    Fletcher-32 would not do: a short chunk all overwritten with zeros passes it)."""
    data = np.frombuffer(text.encode("utf-8"), np.uint8)
    f.create_dataset(name, data=data, chunks=(max(1, min(data.size, 1 << 20)),),
                     maxshape=(None,), compression="gzip")


def _superblock(path: str) -> tuple[int, int] | None:
    """(consistency flags, end-of-file address) of an HDF5 file's version 2 or 3
    superblock at its start (HDF5 file format specification, "Superblock"), or None."""
    with open(path, "rb") as f:
        head = f.read(48)
    if len(head) < 48 or head[:8] != SIGNATURE or head[8] not in (2, 3) or head[9] != 8:
        return None
    flags = head[11]
    base, _, eof, _ = struct.unpack("<4Q", head[12:44])
    return flags, base + eof


_attempts_setter: list = []


def _set_read_attempts():
    """HDF5's ``H5Pset_metadata_read_attempts`` from the library h5py uses (h5py does not
    offer it), or None where it cannot be found."""
    if not _attempts_setter:
        try:
            import h5py
            function = ctypes.CDLL(h5py.h5p.__file__).H5Pset_metadata_read_attempts
            function.argtypes = [ctypes.c_int64, ctypes.c_uint]
            function.restype = ctypes.c_int
        except (OSError, AttributeError):
            function = None
        _attempts_setter.append(function)
    return _attempts_setter[0]


def _open_swmr(h5py, path: str):
    fapl = h5py.h5p.create(h5py.h5p.FILE_ACCESS)
    fapl.set_fclose_degree(h5py.h5f.CLOSE_STRONG)
    _set_read_attempts()(fapl.id, READ_ATTEMPTS)
    fid = h5py.h5f.open(os.fsencode(path), h5py.h5f.ACC_RDONLY | h5py.h5f.ACC_SWMR_READ,
                        fapl=fapl)
    return h5py.File(fid)


def _hdf5_words(error: BaseException) -> str:
    """HDF5's own words for what went wrong, without h5py's wrapping."""
    text = error.args[0] if error.args and isinstance(error.args[0], str) else str(error)
    text = text or type(error).__name__
    if "(" in text and text.endswith(")"):          # "Can't open object (reason)"
        inner = text[text.index("(") + 1:-1]
        return inner or text
    return text


class RecordingFile:
    """An ikaros recording open for reading, checked: ``rows`` is how many rows may be
    read (those written whole and present in the file), ``damage`` says what is missing
    when that is fewer than the file counts (None when nothing is). Every error is a
    RecordingError naming the file, except ValueError for a file that is HDF5 but not
    an ikaros recording."""

    def __init__(self, path: str):
        import h5py
        self.path = path
        self.writing = False        # whether the file is marked as being written
        deadline = time.monotonic() + SETTLE_SECONDS
        while True:
            self.damage = None
            try:
                self._open_and_check(h5py)
                return
            except RecordingError:  # a file being written: its writer may be flushing
                if not self.writing or time.monotonic() >= deadline:
                    raise
            time.sleep(0.02)

    def _open_and_check(self, h5py) -> None:
        self._file = self._open(h5py)
        try:
            self._check()
        except BaseException:
            self._file.close()
            raise

    # --- opening ---------------------------------------------------------------------
    def _open(self, h5py):
        path = self.path
        try:
            self.size = os.path.getsize(path)
            superblock = _superblock(path)
        except OSError as e:
            raise RecordingError(f"cannot read the recording {path}: "
                                 f"{e.strerror or e}") from None
        flags, end = superblock if superblock else (0, 0)
        self.writing = bool(flags & SWMR_WRITING)
        self.cut = self.size < end
        if self.cut:
            self._cut_text = (f"is cut off: the file has {self.size} of the {end} bytes "
                              f"it says it holds")
            if _set_read_attempts() is None:
                raise self._error(None)
        try:
            if not self.cut and not flags & (WRITING | SWMR_WRITING):
                return h5py.File(path, "r")
            if _set_read_attempts() is None:            # HDF5's own retries, then
                return h5py.File(path, "r", swmr=True)
            return _open_swmr(h5py, path)
        except Exception as e:      # noqa: BLE001: every failure of HDF5 is told the same way
            raise self._error(e) from None

    def _error(self, error: BaseException | None, where: str = "") -> RecordingError:
        """One line for a failure of HDF5 on this file (None: a file cut off)."""
        if self.cut:
            return RecordingError(f"the recording {self.path} {self._cut_text}; nothing "
                                  f"in it can be read")
        if where or isinstance(error, (KeyError, RuntimeError, ValueError)):
            return RecordingError(f"the recording {self.path} is damaged: "
                                  f"{where}{_hdf5_words(error)}")
        return RecordingError(f"cannot read the recording {self.path}: "
                              f"{_hdf5_words(error)}")

    # --- what the file says it holds, against what it holds ----------------------------
    def _check(self) -> None:
        f = self._file
        try:
            if "format" not in f.attrs or "tick" not in f:
                raise NotARecording(f"{self.path} is not an ikaros recording")
            self.version = int(f.attrs.get("format_version", 1))
            if self.version < 3:        # before HDF5 reads the unchecked text
                damage = heap_damage(self.path, self._values_start()) or \
                    text_length_damage(self.path, f["model"].id.get_offset(), self.size)
                if damage:
                    raise RecordingError(f"the recording {self.path} is damaged: {damage}")
            kind = f.attrs.get("format")
            if (kind.decode() if isinstance(kind, bytes) else kind) != FORMAT:
                raise NotARecording(f"{self.path} is not an ikaros recording")
            if self.version >= 3:
                self.header = json.loads(self._text("header"))
            else:
                self.header = legacy_header(f.attrs)
            self.header.update({key: f.attrs[key].item() for key in NUMBERS})
            self.model = self._text("model")
            if "\0" in self.model or not self.model.strip():    # (zeros written over it)
                raise RecordingError(f"the recording {self.path} is damaged: its model "
                                     f"text is empty or holds NUL characters")
            self.signals = [(str(name), tuple(int(n) for n in shape), int(start),
                             int(stop))
                            for name, shape, start, stop in self.header["signals"]]
            self.rows = self._whole_rows()
        except (RecordingError, NotARecording):
            raise
        except Exception as e:      # noqa: BLE001
            raise self._error(e) from None

    def _values_start(self) -> int:
        """Where the recorded values begin: the first chunk of "data" or "tick" (the text
        of a format 1 or 2 recording is written before them), else the file's end."""
        starts = [self.size]
        for name in ("data", "tick"):
            dataset = self._file.get(name)
            if dataset is not None and dataset.chunks is not None and dataset.id.get_num_chunks():
                starts.append(dataset.id.get_chunk_info(0).byte_offset)
        return min(starts)

    def _text(self, name: str) -> str:
        """A text of the file: UTF-8 bytes with a checksum (format 3), or a variable-length
        string (format 1 and 2)."""
        value = self._file[name][()]
        if isinstance(value, np.ndarray):
            return value.tobytes().decode("utf-8")
        return value.decode() if isinstance(value, bytes) else str(value)

    def _whole_rows(self) -> int:
        """The rows counted in "stored" (format 2 on) whose chunks are all in the file."""
        f = self._file
        names = TIME_SERIES + (("data",) if f["data"].shape[1] else ())
        shapes = {name: f[name].shape[0] for name in names}
        n = min(shapes.values())
        if "stored" in f:
            counts = f["stored"][:]
            stored = int(counts[0])
            if self.version >= 3 and (counts.size != 2 or counts[1] != ~counts[0]):
                raise RecordingError(f"the recording {self.path} is damaged: its count of "
                                     f"rows written whole is not what it was written as")
            closed = int(f.attrs["ticks_recorded"]) if self.header["finished"] and \
                "ticks_recorded" in f.attrs else stored
            if self.version >= 3 and not (0 <= stored <= n and stored == closed):
                raise RecordingError(f"the recording {self.path} is damaged: it counts "
                                     f"{stored} rows written whole, but holds {n} and was "
                                     f"closed with {closed}")
            n = min(n, max(stored, 0))
        whole = min([n] + [self._rows_in_file(f[name]) for name in names])
        if whole < n:
            what = self._cut_text if self.cut else "is damaged: chunks of its values are " \
                                                    "missing"
            if whole == 0:
                raise RecordingError(f"the recording {self.path} {what}; none of its {n} "
                                     f"rows can be read")
            self.damage = (f"the recording {self.path} {what}; only its first {whole} of "
                           f"{n} rows are read")
        return whole

    def _rows_in_file(self, dataset) -> int:
        """The rows of a chunked dataset from the first up to the first chunk missing or
        not wholly in the file."""
        if dataset.chunks is None:          # contiguous (format 1)
            offset = dataset.id.get_offset()
            whole = offset is not None and \
                offset + dataset.id.get_storage_size() <= self.size
            return dataset.shape[0] if whole else 0
        per_chunk = dataset.chunks[0]
        present = set()

        def keep(info):
            if info.byte_offset is not None and info.byte_offset + info.size <= self.size:
                present.add(info.chunk_offset[0] // per_chunk)
        dataset.id.chunk_iter(keep)
        k = 0
        while k in present:
            k += 1
        return k * per_chunk

    # --- reading ---------------------------------------------------------------------
    def read(self, name: str, start: int, stop: int, columns: slice | None = None):
        """Rows ``start`` to ``stop`` of a dataset (and ``columns`` of "data"); a value
        that fails HDF5's checks is a RecordingError naming the rows."""
        try:
            dataset = self._file[name]
            return dataset[start:stop] if columns is None else dataset[start:stop, columns]
        except Exception as e:      # noqa: BLE001
            raise self._error(e, f"{name}, rows {start} to {stop - 1}: ") from None

    def parameter_changes(self) -> list[tuple[int, str, str]]:
        try:
            changes = self._file["parameter_changes"][:]
        except Exception as e:      # noqa: BLE001
            raise self._error(e, "its parameter changes: ") from None
        return [(int(c["tick"]), c["path"].decode(), c["value"].decode()) for c in changes]

    @property
    def chunk_rows(self) -> int:
        """The rows of one chunk of "data" (values are best read a chunk at a time), or
        1024 when it is not chunked."""
        chunks = self._file["data"].chunks
        return chunks[0] if chunks else 1024

    def close(self) -> None:
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def check_time_series(recording: RecordingFile, ticks: np.ndarray, times: np.ndarray,
                      real_times: np.ndarray) -> None:
    """Refuse time series that damage has changed: every time is its tick × tick_duration,
    as the recorder writes it (format 2 on); a recording of format 1 or 2, which has no
    checksums on its values, must also have tick numbers that increase and real times that
    do not go back, nor are 0 after the first row."""
    damaged = f"the recording {recording.path} is damaged:"
    if recording.version >= 2:
        off = np.flatnonzero(times != ticks * float(recording.header["tick_duration"]))
        if off.size:
            raise RecordingError(f"{damaged} the time of its row {off[0]} is not its tick "
                                 f"times tick_duration")
    if recording.version >= 3:
        return
    # (only the first row's real time is 0: rows are ticks apart)
    for name, back in (("tick", np.diff(ticks) <= 0),
                       ("real_time", (np.diff(real_times) < 0) | (real_times[1:] == 0))):
        bad = np.flatnonzero(back)
        if bad.size:
            raise RecordingError(f"{damaged} its {name} values are out of order at row "
                                 f"{bad[0] + 1} (a recording of format "
                                 f"{recording.version}, without checksums)")
