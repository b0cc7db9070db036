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
            def shuffle4(words, n, out):
                """Each piece of ``n`` words of ``words``, shuffled, into ``out``."""
                for start in range(0, words.size, n):
                    k = min(n, words.size - start)
                    w = words[start:start + k]
                    o = out[4 * start:4 * (start + k)]
                    for i in range(k):
                        v = w[i]
                        o[i] = v & 0xFF
                        o[k + i] = (v >> 8) & 0xFF
                        o[2 * k + i] = (v >> 16) & 0xFF
                        o[3 * k + i] = (v >> 24) & 0xFF
            _shuffle.append(shuffle4)
    return _shuffle[0]


def shuffled(rows: np.ndarray, piece: int | None = None) -> np.ndarray:
    """The bytes of a C-contiguous float32 array as HDF5's shuffle filter orders them: every
    value's first byte, then every second byte, and so on; with ``piece``, each piece of
    that many rows on its own (in one call, which lets the GIL go once)."""
    values = rows.size if piece is None else piece * int(np.prod(rows.shape[1:]))
    shuffle4 = _numba_shuffle()
    if shuffle4 is None:
        flat = rows.reshape(-1)
        return np.concatenate([
            np.ascontiguousarray(flat[k:k + values].view(np.uint8).reshape(-1, 4).T).ravel()
            for k in range(0, flat.size, max(values, 1))] or [np.zeros(0, np.uint8)])
    out = np.empty(rows.size * 4, np.uint8)
    shuffle4(rows.reshape(-1).view(np.uint32), max(values, 1), out)
    return out


def shuffled_deflate(rows: np.ndarray, piece: int) -> list[bytes]:
    """The chunks of ``piece`` rows each of a C-contiguous float32 array (the last may be
    shorter) as HDF5's shuffle and deflate filters would store them."""
    data = shuffled(rows, piece)
    size = 4 * piece * int(np.prod(rows.shape[1:]))
    return [_deflate(data[k:k + size], COMPRESSION_LEVEL)
            for k in range(0, data.size, max(size, 1))]
