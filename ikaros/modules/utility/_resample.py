"""Helpers shared by the modules that move the content of a matrix about its centre
(MatrixRotation, MatrixScale) or shift it (MatrixTranslation)."""
import numpy as np


def round_half_away(v):
    """``v`` rounded to the nearest whole number, halves away from zero (as in C)."""
    return np.where(v >= 0, np.floor(v + 0.5), np.ceil(v - 0.5))


CENTRES = "half/middle"
CENTRE_HELP = ("the centre of the matrix: half, (cols / 2, rows / 2) as in Ikaros 2; or "
               "middle, ((cols - 1) / 2, (rows - 1) / 2)")


def centre_offsets(x, centre: str = "half"):
    """For a matrix ``x`` (its last two axes; a 1-D ``x`` is one row): its centre, ``half``
    ``(cols / 2, rows / 2)`` (Ikaros 2's) or ``middle`` ``((cols - 1) / 2, (rows - 1) / 2)``,
    and every element's offset from it, as ``(cx, cy, dx, dy)`` with ``dx`` and ``dy`` of
    shape (rows, cols)."""
    rows, cols = (x.shape[-2], x.shape[-1]) if x.ndim > 1 else (1, x.shape[0])
    y, xs = np.mgrid[0:rows, 0:cols].astype(np.float64)
    cx, cy = ((cols - 1) / 2, (rows - 1) / 2) if centre == "middle" else (cols / 2, rows / 2)
    return cx, cy, xs - cx, y - cy


def resample(x, out, src_x, src_y):
    """out[..., i, j] = x[..., src_y[i, j], src_x[i, j]] with the coordinates rounded to the
    nearest element (halves away from zero); 0 where the source falls outside."""
    sx = round_half_away(src_x)
    sy = round_half_away(src_y)
    m = x if x.ndim > 1 else x.reshape(1, -1)
    o = out if out.ndim > 1 else out.reshape(1, -1)
    rows, cols = m.shape[-2], m.shape[-1]
    inside = (sx >= 0) & (sx < cols) & (sy >= 0) & (sy < rows)
    o.fill(0)
    o[..., inside] = m[..., sy[inside].astype(np.intp), sx[inside].astype(np.intp)]
