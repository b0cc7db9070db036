"""What a recording does when writing it fails (a full disk, a file-size limit), whatever
its file format: the run stops (``on_error="stop"``, the default) or goes on without the
recording (``"continue"``), and the one-line message names the file, why, and the ticks
the file holds. A disk full already at the start is found before the file is handed to
the format's library (``probe_room``), and a file that holds nothing is removed."""
from __future__ import annotations

import os
import re

ON_ERROR = ("stop", "continue")


def check_on_error(on_error: str) -> str:
    """``on_error`` itself, or a ValueError naming the choices."""
    if on_error not in ON_ERROR:
        raise ValueError(f'on_error must be "stop" or "continue", not "{on_error}"')
    return on_error


def reason(error: BaseException) -> str:
    """The operating system's words for a failed write ("No space left on device"), else
    the error's own text."""
    errno = getattr(error, "errno", None)
    if not errno:
        found = re.search(r"errno = (\d+)", str(error))
        errno = int(found.group(1)) if found else None
    if errno:
        return os.strerror(errno)
    return str(error) or type(error).__name__


def kept_text(stored: int, first_tick: int | None, last_tick: int | None) -> str:
    """What a cut-off recording holds, e.g. "it holds 1200 ticks (0 to 1199)"."""
    if stored == 0 or first_tick is None:
        return "it holds no ticks (the file is removed)"
    return f"it holds {stored} ticks ({first_tick} to {last_tick})"


def failure_text(filename: str, error: BaseException, stored: int, first_tick,
                 last_tick, on_error: str) -> str:
    """The one line that reports a failed recording."""
    then = "the run goes on without recording" if on_error == "continue" else \
        "the run stops"
    return (f"writing the recording {filename} failed ({reason(error)}); "
            f"{kept_text(stored, first_tick, last_tick)}; {then}")


def probe_room(filename: str, size: int) -> None:
    """Write ``size`` bytes into the file (then empty it): a disk already full fails here,
    in plain writes, before a file format's library is given the file (HDF5 does not
    recover from a failed write of its header)."""
    with open(filename, "wb") as f:
        try:
            f.write(bytes(size))
            f.flush()
        finally:
            f.seek(0)
            f.truncate(0)


def remove_recording(filename: str, only_empty: bool = False) -> None:
    """Remove a recording that holds nothing (if it is there; ``only_empty``: if it is
    an empty file)."""
    try:
        if not only_empty or os.path.getsize(filename) == 0:
            os.remove(filename)
    except OSError:
        pass

