"""Tests of the shared vision helpers in ikaros/modules/vision/_cv.py."""
import numpy as np
import pytest

from ikaros.modules.vision._cv import (GrayImage, Uint8Image, check_image, pixel_of,
                                       position_of, shrunk)


def test_uint8_levels_are_the_rounded_clipped_values():
    x = np.array([[-0.2, 0.0, 0.5 / 255, 1.5 / 255, 0.5, 100.4 / 255, 1.0, 1.3]], np.float32)
    levels = Uint8Image(x.shape)(x)
    assert levels.dtype == np.uint8
    assert np.array_equal(levels, [[0, 0, 0, 2, 128, 100, 255, 255]])
    r = np.random.default_rng(0).random((50, 60)).astype(np.float32)
    assert np.array_equal(Uint8Image(r.shape)(r), np.rint(r * 255).astype(np.uint8))


def test_gray_image_is_a_view_of_gray_and_the_intensity_of_colour():
    gray = np.ones((4, 5), np.float32)
    assert GrayImage(gray)() is gray
    colour = np.stack([np.full((4, 5), v, np.float32) for v in (0.3, 0.6, 0.9)])
    make = GrayImage(colour)
    out = make()
    assert out.shape == (4, 5) and np.allclose(out, 0.6)
    colour[0] = 0.0
    assert make() is out and np.allclose(out, 0.5)


def test_shapes():
    assert shrunk((3, 10, 12), 5) == (3, 6, 8)
    assert shrunk((10, 12), 3, 1) == (8, 12)
    with pytest.raises(ValueError, match="smaller than the kernel"):
        shrunk((4, 4), 5)
    check_image((3, 2, 2))
    for bad in ((4, 2, 2), (5,), (0, 3)):
        with pytest.raises(ValueError, match="gray \\(rows, cols\\) or colour"):
            check_image(bad)


def test_positions_are_fractions_with_pixel_centres():
    assert position_of(2, 3, 10, 20) == (3.5 / 20, 2.5 / 10)
    assert pixel_of(*position_of(2, 3, 10, 20), 10, 20) == (2, 3)
    assert pixel_of(0.0, 0.0, 10, 20) == (0, 0)
    assert pixel_of(1.0, 1.0, 10, 20) == (9, 19)         # the far edges clamp inside
    assert pixel_of(-0.5, 2.0, 10, 20) == (9, 0)
