"""Saves from the editor that never lose another editor's: ``GET /api/model`` gives the
version of the model's file (a hash of its bytes), a save carries the version its edits
were made from, and a save over another version (another editor saved since, or the file
was edited on disk) is refused with 409 and the file's version now, so the editor can
offer to reload or to overwrite. A save without a version writes as it is told."""
from __future__ import annotations

import hashlib
import threading

from ..language.writer import write_file

_saving = threading.Lock()     # the check and the write of one save, then the next


class SaveConflict(Exception):
    """The file is not at the version the edits were made from."""

    def __init__(self, version: str | None):
        super().__init__(version)
        self.version = version        # the file's version now (None: there is no file)


def file_version(path: str | None) -> str | None:
    """The version of a model file: a hash of its bytes; None when there is no file."""
    if not path:
        return None
    try:
        with open(path, "rb") as f:
            return hashlib.sha256(f.read()).hexdigest()[:20]
    except FileNotFoundError:
        return None


def save(tree, path: str, version: str | None, check: bool) -> str | None:
    """Write ``tree`` to ``path`` and return the file's new version; with ``check``,
    SaveConflict unless the file is at ``version`` now."""
    with _saving:
        if check:
            current = file_version(path)
            if current != version:
                raise SaveConflict(current)
        write_file(tree, path)
        return file_version(path)
