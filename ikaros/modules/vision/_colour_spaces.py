"""The colour-space formulas of ColorTransform, in plain NumPy on (3, rows, cols) arrays.

RGB is taken with the BT.709 (sRGB) primaries and the D65 white. The original Ikaros
(2 and 3) applies no gamma: its RGB values are linear. The six-digit matrices and the white
are the ones its outputs show (the golden files of Ikaros 3 fit them to 1e-7).
"""
from __future__ import annotations

import numpy as np

RGB_TO_XYZ = np.array([[0.412453, 0.357581, 0.180423],
                       [0.212670, 0.715160, 0.072169],
                       [0.019334, 0.119193, 0.950227]])
XYZ_TO_RGB = np.array([[3.240479, -1.537150, -0.498535],
                       [-0.969256, 1.875992, 0.041556],
                       [0.055648, -0.204043, 1.057311]])
WHITE = np.array([0.950456, 1.0, 1.088754])[:, None, None]       # D65, Y = 1

_EPSILON = 0.008856             # (6/29)³: where the cube root of L*a*b* meets its line
_SLOPE = 7.787                  # the line's slope, (29/6)² / 3


# RGB->XYZ divided by the white, in single precision: the original's RGB->Lab computes in
# float with these (its golden outputs of Ikaros 2 and 3 agree to the last bit with them)
RGB_TO_WHITE_XYZ = (RGB_TO_XYZ / WHITE[:, :, 0]).astype(np.float32)


def rgb_to_lab_float32(planes, out: np.ndarray) -> None:
    """CIE L*a*b* of linear RGB planes (three (rows, cols) float32 arrays) into ``out``
    (3, rows, cols), in single precision as the original: X/Xn = Σ m·(R, G, B) in that
    order, f(t) = t^(1/3) above 0.008856 and 7.787 t + 16/116 otherwise, L = 116 f(Y) - 16
    (not below 0), a = 500 (f(X) - f(Y)), b = 200 (f(Y) - f(Z))."""
    f = np.empty((3,) + out.shape[1:], np.float32)
    for k in range(3):
        m = RGB_TO_WHITE_XYZ[k]
        t = planes[0] * m[0]
        t += planes[1] * m[1]
        t += planes[2] * m[2]
        f[k] = np.where(t > np.float32(_EPSILON), np.cbrt(t),
                        t * np.float32(_SLOPE) + np.float32(16.0 / 116.0))
    np.maximum(f[1] * np.float32(116.0) - np.float32(16.0), 0.0, out=out[0])
    np.multiply(f[0] - f[1], np.float32(500.0), out=out[1])
    np.multiply(f[1] - f[2], np.float32(200.0), out=out[2])


def mix(matrix: np.ndarray, planes: np.ndarray) -> np.ndarray:
    """Each output plane as the matrix's weighted sum of the three input planes."""
    return np.einsum("ij,jrc->irc", matrix, planes)


def xyz_to_lab(xyz: np.ndarray) -> np.ndarray:
    """CIE L*a*b* (L 0..100) of XYZ relative to the D65 white."""
    t = xyz / WHITE
    f = np.where(t > _EPSILON, np.cbrt(t), _SLOPE * t + 16.0 / 116.0)
    return np.stack([116.0 * f[1] - 16.0, 500.0 * (f[0] - f[1]), 200.0 * (f[1] - f[2])])


def lab_to_xyz(lab: np.ndarray) -> np.ndarray:
    """The inverse of ``xyz_to_lab``."""
    fy = (lab[0] + 16.0) / 116.0
    f = np.stack([fy + lab[1] / 500.0, fy, fy - lab[2] / 200.0])
    return np.where(f > 6.0 / 29.0, f ** 3, (f - 16.0 / 116.0) / _SLOPE) * WHITE


def srgb_expand(values: np.ndarray) -> np.ndarray:
    """sRGB-encoded values 0..1 to linear light (IEC 61966-2-1)."""
    return np.where(values <= 0.04045, values / 12.92, ((values + 0.055) / 1.055) ** 2.4)


def srgb_compress(linear: np.ndarray) -> np.ndarray:
    """Linear light to sRGB-encoded values, the inverse of ``srgb_expand``."""
    linear = np.maximum(linear, 0.0)
    return np.where(linear <= 0.0031308, 12.92 * linear,
                    1.055 * linear ** (1.0 / 2.4) - 0.055)
