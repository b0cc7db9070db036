"""Tests of the InputJPEG module (and the image convention it shares with InputPNG)."""
import sys

import numpy as np
import pytest
from PIL import Image

from ikaros.errors import ModelError, RunError
from ikaros.module import PRINT, WARNING
from ikaros.testing import load_body as load


def save_jpeg(path, array):
    """Save (rows, cols) gray or (rows, cols, 3) colour bytes; return what Pillow decodes."""
    mode = "L" if array.ndim == 2 else "RGB"
    Image.fromarray(array.astype(np.uint8), mode).save(path, quality=95)
    with Image.open(path) as img:
        return np.asarray(img.convert("RGB"), dtype=np.float64) / 255   # (rows, cols, 3)


def check_outputs(net, rgb):
    """The outputs against an image decoded independently: (rows, cols, 3) in 0..1."""
    planes = rgb.transpose(2, 0, 1)
    assert np.allclose(net.output("I.OUTPUT"), planes, atol=1e-6)
    assert np.allclose(net.output("I.RED"), planes[0], atol=1e-6)
    assert np.allclose(net.output("I.GREEN"), planes[1], atol=1e-6)
    assert np.allclose(net.output("I.BLUE"), planes[2], atol=1e-6)
    assert np.allclose(net.output("I.INTENSITY"), planes.mean(axis=0), atol=1e-6)


def test_colour_file(tmp_path):
    rng = np.random.default_rng(1)
    rgb = save_jpeg(tmp_path / "c.jpg", rng.integers(0, 256, (6, 9, 3)))
    net = load(tmp_path, '<module class="InputJPEG" name="I" filename="c.jpg"/>')
    try:
        assert net.output("I.OUTPUT").shape == (3, 6, 9)
        assert net.output("I.INTENSITY").shape == (6, 9)
        check_outputs(net, rgb)              # already in init
        net.run(ticks=3)
        check_outputs(net, rgb)
        assert net.tick == 3                 # iterations="0" (default): forever
    finally:
        net.close()


def test_gray_file_gives_equal_planes(tmp_path):
    gray = np.arange(20).reshape(4, 5) * 12
    rgb = save_jpeg(tmp_path / "g.jpg", gray)
    net = load(tmp_path, '<module class="InputJPEG" name="I" filename="g.jpg"/>')
    try:
        net.step()
        check_outputs(net, rgb)
        assert np.array_equal(net.output("I.RED"), net.output("I.BLUE"))
        assert np.allclose(net.output("I.INTENSITY"), net.output("I.GREEN"))
        assert abs(net.output("I.INTENSITY")[2, 3] - gray[2, 3] / 255) < 0.03
    finally:
        net.close()


def test_numbered_sequence_iterations_and_end_of_file(tmp_path):
    images = [save_jpeg(tmp_path / f"s{i:02d}.jpg", np.full((3, 4), 40 * (i + 1)))
              for i in range(3)]
    net = load(tmp_path, '<module class="InputJPEG" name="I" filename="s%02d.jpg" '
                         'filecount="3" iterations="2"/>')
    try:
        check_outputs(net, images[0])
        for tick in range(6):
            net.step()
            check_outputs(net, images[tick % 3])
        assert net.tick == 6                 # end of file after two passes
        with pytest.raises(RunError, match="end_of_file"):
            net.step()
    finally:
        net.close()


def test_read_once_no_reads_the_file_again(tmp_path):
    first = save_jpeg(tmp_path / "x.jpg", np.full((2, 2), 200))
    once = load(tmp_path, '<module class="InputJPEG" name="I" filename="x.jpg"/>')
    again = load(tmp_path, '<module class="InputJPEG" name="I" filename="x.jpg" '
                           'read_once="no"/>')
    try:
        once.step()
        again.step()
        second = save_jpeg(tmp_path / "x.jpg", np.full((2, 2), 10))
        once.step()
        again.step()
        check_outputs(once, first)
        check_outputs(again, second)
    finally:
        once.close()
        again.close()


def test_later_file_of_another_size_is_resized_and_missing_file_warns(tmp_path):
    save_jpeg(tmp_path / "f0.jpg", np.full((4, 6), 100))
    save_jpeg(tmp_path / "f1.jpg", np.full((8, 12), 100))
    net = load(tmp_path, '<module class="InputJPEG" name="I" filename="f%d.jpg" '
                         'filecount="3"/>')
    try:
        net.step()
        before = net.output("I.INTENSITY").copy()
        net.step()
        assert net.output("I.INTENSITY").shape == (4, 6)
        assert np.allclose(net.output("I.INTENSITY"), before, atol=0.02)
        net.step()                            # f2.jpg does not exist: the image stays
        net.step()
        assert np.allclose(net.output("I.INTENSITY"), before, atol=0.02)
        warnings = [e for e in net.log if e[1] == WARNING and "f2.jpg" in e[3]]
        assert len(warnings) == 1
    finally:
        net.close()


def test_missing_file_and_missing_filename_are_build_errors(tmp_path):
    with pytest.raises(ModelError, match="nothere.jpg"):
        load(tmp_path, '<module class="InputJPEG" name="I" filename="nothere.jpg"/>')
    with pytest.raises(ModelError, match="needs a filename"):
        load(tmp_path, '<module class="InputJPEG" name="I"/>')


def test_missing_pillow_fails_at_load_with_the_pip_install(tmp_path, monkeypatch):
    save_jpeg(tmp_path / "c.jpg", np.zeros((2, 2)))
    monkeypatch.setitem(sys.modules, "PIL", None)        # import PIL now fails
    monkeypatch.setitem(sys.modules, "PIL.Image", None)
    with pytest.raises(ModelError, match="pip install") as info:
        load(tmp_path, '<module class="InputJPEG" name="I" filename="c.jpg"/>')
    assert "Pillow" in str(info.value)


def test_outputs_feed_other_modules_as_images(tmp_path):
    rgb = save_jpeg(tmp_path / "c.jpg", np.random.default_rng(2).integers(0, 256, (3, 3, 3)))
    net = load(tmp_path, '<module class="InputJPEG" name="I" filename="c.jpg"/>\n'
                         '<module class="Scale" name="S" factor="2"/>\n'
                         '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("S.OUTPUT"), 2 * rgb.transpose(2, 0, 1), atol=1e-5)
        assert not [e for e in net.log if e[1] < PRINT]
    finally:
        net.close()
