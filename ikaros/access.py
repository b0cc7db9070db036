"""What files a build may touch. A model loaded from the command line or ``ikaros.load`` may
use any file its user can; a model sent through the web UI is confined (see
``ikaros.webui.confine``): its includes, group files, class folders and file parameters
must name files inside the allowed folders, by relative names without ``..``.

The reader, the builder and the kernel ask ``current()`` (None: no confinement).
"""
from __future__ import annotations

import contextlib
import contextvars
import os
import re

_FILE_PARAMETER = re.compile(r"(?:^|_)(?:file|filename|files|directory|dir|folder|path)$",
                             re.I)


class AccessRefused(PermissionError):
    """A confined model named a file outside its folders; the caller names the element."""


class Confinement:
    """Files may be used only inside ``folders`` (real paths; symbolic links are followed
    before the check)."""

    def __init__(self, folders):
        self.folders = tuple(dict.fromkeys(os.path.realpath(f) for f in folders if f))

    def inside(self, path: str) -> bool:
        real = os.path.realpath(path)
        return any(real == f or real.startswith(f + os.sep) for f in self.folders)

    def check(self, name: str, base: str, what: str) -> str:
        """The path of file ``name`` relative to folder ``base``; AccessRefused when it is
        absolute, climbs with ``..`` or ends up outside the folders."""
        parts = re.split(r"[\\/]", name)
        if os.path.isabs(name) or name.startswith("~") or ".." in parts:
            raise AccessRefused(f'{what} "{name}" is refused: a model from the web UI may '
                                f'only name files by a relative path without ".."')
        path = os.path.join(base, name)
        if not self.inside(path):
            raise AccessRefused(f'{what} "{name}" is refused: it is outside the models '
                                f'folder')
        return path


_current: contextvars.ContextVar[Confinement | None] = contextvars.ContextVar(
    "ikaros_access", default=None)


def current() -> Confinement | None:
    """The confinement of the build under way in this thread, or None (full access)."""
    return _current.get()


@contextlib.contextmanager
def applied(confinement: Confinement | None):
    token = _current.set(confinement)
    try:
        yield
    finally:
        _current.reset(token)


def is_file_parameter(spec) -> bool:
    """Whether a parameter names a file or folder: declared with ``file=True``, or a string
    parameter named like one (``filename``, ``read_file``, ``directory`` ...)."""
    return bool(getattr(spec, "file", False)) or \
        (spec.type == "string" and bool(_FILE_PARAMETER.search(spec.name)))


def check_file_parameter(spec, value, base: str) -> None:
    """Refuse a file parameter of a confined build that names a file outside the folders."""
    confinement = current()
    if confinement is None or not isinstance(value, str) or not value.strip():
        return
    if is_file_parameter(spec):
        confinement.check(value.strip(), base, f'parameter "{spec.name}"')
