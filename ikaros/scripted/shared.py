"""The inputs and outputs of a scripted module in memory that the kernel and its worker
share: one memory-mapped file (in /dev/shm where there is one), so that a tick moves no
array through the pipe.

The kernel creates the file and maps it; the worker maps it and removes its name at once,
so nothing is left behind however either process ends (``multiprocessing.shared_memory``
is not used: its resource tracker would unlink or warn about memory that another process
created). This file is run by the worker too: it needs only the standard library and NumPy.
"""
from __future__ import annotations

import mmap
import os
import tempfile

import numpy as np

_ALIGN = 64
_FOLDER = "/dev/shm" if os.path.isdir("/dev/shm") else None


class SharedArrays:
    """float32 arrays by key in one shared mapping; ``description`` tells the other
    process where each one is."""

    def __init__(self, path: str, size: int, layout: dict[str, tuple[int, tuple]],
                 fd: int):
        self.description = {"file": path, "size": size,
                            "layout": {k: [o, list(s)] for k, (o, s) in layout.items()}}
        self.path = path
        self._map = mmap.mmap(fd, size)
        self.arrays = {key: np.frombuffer(self._map, np.float32, int(np.prod(shape)),
                                          offset).reshape(shape)
                       for key, (offset, shape) in layout.items()}

    @classmethod
    def create(cls, shapes: dict[str, tuple]) -> "SharedArrays":
        """New shared arrays (zeros) of these shapes (the kernel's side)."""
        layout, size = {}, 0
        for key, shape in shapes.items():
            layout[key] = (size, tuple(int(s) for s in shape))
            size += -(-int(np.prod(shape, dtype=np.int64)) * 4 // _ALIGN) * _ALIGN
        size = max(size, _ALIGN)
        fd, path = tempfile.mkstemp(prefix="ikaros-script-", dir=_FOLDER)
        try:
            os.ftruncate(fd, size)
            return cls(path, size, layout, fd)
        except BaseException:
            os.unlink(path)
            raise
        finally:
            os.close(fd)

    @classmethod
    def open(cls, description: dict) -> "SharedArrays":
        """The arrays another process created (the worker's side); the file's name is
        removed, the memory stays mapped."""
        path = description["file"]
        fd = os.open(path, os.O_RDWR)
        try:
            layout = {k: (o, tuple(s)) for k, (o, s) in description["layout"].items()}
            return cls(path, description["size"], layout, fd)
        finally:
            os.close(fd)
            unlink(path)


def unlink(path: str) -> None:
    """Remove a shared file's name (the first of the two processes to do it wins)."""
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
