"""Tests of the InputImage module (Ikaros 3's image reader)."""
import numpy as np
import pytest
from PIL import Image

from ikaros.errors import ModelError
from ikaros.testing import load_body as load


def test_reads_png_and_a_hash_numbered_sequence(tmp_path):
    for k in range(3):
        Image.fromarray(np.full((2, 3), 50 * k, np.uint8), "L").save(tmp_path / f"s_{k:02d}.png")
    net = load(tmp_path, '<module class="InputImage" name="I" filename="s_##.png" '
                         'filecount="3"/>', dialect=2)      # ticks from 0
    try:
        got = []
        for _ in range(4):
            net.step()
            got.append(float(net.output("I.INTENSITY")[0, 0]) * 255)
        assert np.allclose(got, [0, 50, 100, 0], atol=1e-4)
        assert net.output("I.OUTPUT").shape == (3, 2, 3)
    finally:
        net.close()


def test_reads_jpeg(tmp_path):
    Image.fromarray(np.full((4, 4, 3), (255, 0, 0), np.uint8), "RGB").save(
        tmp_path / "r.jpg", quality=100)
    net = load(tmp_path, '<module class="InputImage" name="I" filename="r.jpg"/>')
    try:
        net.step()
        assert np.allclose(net.output("I.RED"), 1, atol=0.02)
        assert np.allclose(net.output("I.GREEN"), 0, atol=0.02)
    finally:
        net.close()


def test_two_hashes_number_at_most_100_files(tmp_path):
    Image.fromarray(np.zeros((2, 2), np.uint8), "L").save(tmp_path / "f_00.png")
    with pytest.raises(ModelError, match=r'filecount 101 needs more file numbers than '
                                         r'"f_##.png" can write \(100\)'):
        load(tmp_path, '<module class="InputImage" name="I" filename="f_##.png" '
                       'filecount="101"/>')


def test_unreadable_frame_keeps_the_previous_image_with_a_warning(tmp_path):
    Image.fromarray(np.full((2, 2), 255, np.uint8), "L").save(tmp_path / "f_0.png")
    (tmp_path / "f_1.png").write_bytes(b"not an image")
    net = load(tmp_path, '<module class="InputImage" name="I" filename="f_#.png" '
                         'filecount="2"/>')
    try:
        net.run(ticks=2)
        assert np.allclose(net.output("I.INTENSITY"), 1)
        assert any("cannot read image file" in e[3] for e in net.log)
    finally:
        net.close()


def test_read_once_no_reads_the_file_again_on_every_tick(tmp_path):
    Image.fromarray(np.full((2, 2), 200, np.uint8), "L").save(tmp_path / "x.png")
    once = load(tmp_path, '<module class="InputImage" name="I" filename="x.png"/>')
    again = load(tmp_path, '<module class="InputImage" name="I" filename="x.png" '
                           'read_once="no"/>')
    try:
        once.step()
        again.step()
        Image.fromarray(np.full((2, 2), 10, np.uint8), "L").save(tmp_path / "x.png")
        once.step()
        again.step()
        assert np.allclose(once.output("I.INTENSITY"), 200 / 255)
        assert np.allclose(again.output("I.INTENSITY"), 10 / 255)
    finally:
        once.close()
        again.close()
