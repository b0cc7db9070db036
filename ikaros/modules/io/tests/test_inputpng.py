"""Tests of the InputPNG module."""
import numpy as np
import pytest
from PIL import Image

from ikaros.errors import RunError
from ikaros.module import PRINT
from ikaros.testing import load_body as load


def test_colour_png_is_exact(tmp_path):
    rgb = np.random.default_rng(0).integers(0, 256, (5, 7, 3)).astype(np.uint8)
    Image.fromarray(rgb, "RGB").save(tmp_path / "c.png")
    net = load(tmp_path, '<module class="InputPNG" name="I" filename="c.png"/>')
    try:
        planes = rgb.transpose(2, 0, 1) / 255.0
        for _ in range(3):
            net.step()
            assert np.allclose(net.output("I.OUTPUT"), planes, atol=1e-7)
            assert np.allclose(net.output("I.RED"), planes[0], atol=1e-7)
            assert np.allclose(net.output("I.GREEN"), planes[1], atol=1e-7)
            assert np.allclose(net.output("I.BLUE"), planes[2], atol=1e-7)
            assert np.allclose(net.output("I.INTENSITY"), planes.mean(0), atol=1e-7)
    finally:
        net.close()


def test_gray_16_bit_palette_and_alpha(tmp_path):
    gray = np.array([[0, 128, 255], [1, 2, 254]], np.uint8)
    Image.fromarray(gray, "L").save(tmp_path / "g8.png")
    deep = np.array([[0, 32768, 65535]], np.uint16)
    Image.fromarray(deep).save(tmp_path / "g16.png")
    rgba = np.zeros((2, 2, 4), np.uint8)
    rgba[..., 0], rgba[..., 3] = 255, 10                 # red, almost transparent
    Image.fromarray(rgba, "RGBA").save(tmp_path / "a.png")
    Image.fromarray(gray, "L").convert("P").save(tmp_path / "p.png")
    net = load(tmp_path, '<module class="InputPNG" name="G8" filename="g8.png"/>\n'
                         '<module class="InputPNG" name="G16" filename="g16.png"/>\n'
                         '<module class="InputPNG" name="A" filename="a.png"/>\n'
                         '<module class="InputPNG" name="P" filename="p.png"/>')
    try:
        net.step()
        for name in ("RED", "GREEN", "BLUE", "INTENSITY"):
            assert np.allclose(net.output(f"G8.{name}"), gray / 255, atol=1e-7)
            assert np.allclose(net.output(f"P.{name}"), gray / 255, atol=1e-7)
        assert np.allclose(net.output("G16.INTENSITY"), deep / 65535, atol=1e-6)
        assert np.array_equal(net.output("A.RED"), np.ones((2, 2)))       # alpha ignored
        assert np.array_equal(net.output("A.GREEN"), np.zeros((2, 2)))
        assert np.allclose(net.output("A.INTENSITY"), 1 / 3)
    finally:
        net.close()


def test_size_x_and_size_y_resize(tmp_path):
    Image.fromarray(np.full((10, 20, 3), (255, 0, 51), np.uint8), "RGB").save(tmp_path / "c.png")
    net = load(tmp_path, '<module class="InputPNG" name="I" filename="c.png" size_x="5" '
                         'size_y="4"/>')
    try:
        assert net.output("I.OUTPUT").shape == (3, 4, 5)
        net.step()
        assert np.allclose(net.output("I.RED"), 1) and np.allclose(net.output("I.GREEN"), 0)
        assert np.allclose(net.output("I.BLUE"), 0.2)
    finally:
        net.close()


def test_sequence_notify_repeat_and_iterations(tmp_path):
    for i in range(2):
        Image.fromarray(np.full((2, 2), 100 * i, np.uint8), "L").save(tmp_path / f"s{i}.png")
    net = load(tmp_path, '<module class="InputPNG" name="I" filename="s%d.png" filecount="2" '
                         'iterations="3" notify_repeat="yes"/>')
    try:
        got = []
        for _ in range(6):
            net.step()
            got.append(float(net.output("I.INTENSITY")[0, 0]))
        assert np.allclose(got, [0, 100 / 255] * 3)
        repeats = [e for e in net.log if e[1] == PRINT and "starts over" in e[3]]
        assert len(repeats) == 2
        with pytest.raises(RunError):
            net.step()
    finally:
        net.close()
