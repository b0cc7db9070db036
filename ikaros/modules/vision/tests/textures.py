"""Test images for the tracking tests: a random texture with corners everywhere, and copies
of it moved by a known offset."""
import numpy as np


def texture(rows=240, cols=320, seed=1, cell=4):
    """Random gray levels on a grid of ``cell`` x ``cell`` pixel squares, smoothed a little
    by bilinear interpolation: texture with corners everywhere, values 0..1."""
    rng = np.random.default_rng(seed)
    coarse = rng.random((rows // cell + 2, cols // cell + 2))
    r = np.arange(rows) / cell
    c = np.arange(cols) / cell
    r0, c0 = r.astype(int), c.astype(int)
    fr, fc = (r - r0)[:, None], (c - c0)[None, :]
    a = coarse[r0][:, c0]
    b = coarse[r0][:, c0 + 1]
    d = coarse[r0 + 1][:, c0]
    e = coarse[r0 + 1][:, c0 + 1]
    return ((1 - fr) * ((1 - fc) * a + fc * b) + fr * ((1 - fc) * d + fc * e)).astype(np.float32)


def moved(image, dx, dy):
    """``image`` moved dx pixels right and dy down (whole pixels), wrapping round."""
    return np.roll(np.roll(image, int(dy), axis=0), int(dx), axis=1)


def waves(rows=240, cols=320, dx=0.0, dy=0.0, seed=3, count=24):
    """A smooth texture made of ``count`` random plane waves (periods 6 to 30 pixels),
    moved by (dx, dy) pixels exactly, sub-pixel offsets included: the waves are evaluated
    at (x - dx, y - dy). Values 0..1."""
    rng = np.random.default_rng(seed)
    angle = rng.uniform(0, np.pi, count)
    period = rng.uniform(6, 30, count)
    phase = rng.uniform(0, 2 * np.pi, count)
    y, x = np.mgrid[0:rows, 0:cols].astype(np.float64)
    x, y = x - dx, y - dy
    total = sum(np.cos(2 * np.pi * (np.cos(a) * x + np.sin(a) * y) / p + f)
                for a, p, f in zip(angle, period, phase))
    return (0.5 + 0.5 * total / np.sqrt(2 * count) / 2.5).clip(0, 1).astype(np.float32)
