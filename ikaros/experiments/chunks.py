"""A recording's chunks as HDF5's shuffle and deflate filters store them, made without the
GIL where possible so that the kernel thread runs on while the writer thread compresses:
the byte shuffle with numba (``nogil``; NumPy, which holds the GIL, without numba), the
deflate with ISA-L (zlib without it; both let the GIL go)."""
from __future__ import annotations

import numpy as np

try:        # ISA-L's deflate writes the same format as zlib, about 8 times as fast
    from isal.isal_zlib import compress as _deflate
except ImportError:
    from zlib import compress as _deflate

COMPRESSION_LEVEL = 1

_shuffle: list = []        # the numba shuffle, or None without numba


def _numba_shuffle():
    if not _shuffle:
        try:
            from numba import njit
        except ImportError:
            _shuffle.append(None)
        else:
            @njit(nogil=True, cache=True)
            def shuffle4(words, out):
                n = words.size
                for i in range(n):
                    v = words[i]
                    out[i] = v & 0xFF
                    out[n + i] = (v >> 8) & 0xFF
                    out[2 * n + i] = (v >> 16) & 0xFF
                    out[3 * n + i] = (v >> 24) & 0xFF
            _shuffle.append(shuffle4)
    return _shuffle[0]


def shuffled(rows: np.ndarray) -> np.ndarray:
    """The bytes of a C-contiguous float32 array as HDF5's shuffle filter orders them: every
    value's first byte, then every second byte, and so on."""
    shuffle4 = _numba_shuffle()
    if shuffle4 is None:
        return np.ascontiguousarray(rows.view(np.uint8).reshape(-1, 4).T).reshape(-1)
    out = np.empty(rows.size * 4, np.uint8)
    shuffle4(rows.reshape(-1).view(np.uint32), out)
    return out


def shuffled_deflate(rows: np.ndarray) -> bytes:
    """A chunk (a C-contiguous float32 array) as HDF5's shuffle and deflate filters would
    store it."""
    return _deflate(shuffled(rows), COMPRESSION_LEVEL)
