"""Tests of the InputRawImage module."""
import numpy as np
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.module import WARNING
from ikaros.testing import load_body as load


def test_bytes_scaled_to_0_1_row_by_row(tmp_path):
    data = np.arange(0, 256, 17, dtype=np.uint8)[:12]           # 12 bytes: 3 rows × 4
    data.tofile(tmp_path / "x.raw")
    net = load(tmp_path, '<module class="InputRawImage" name="I" filename="x.raw" size_x="4" '
                         'size_y="3"/>')
    try:
        assert net.output("I.OUTPUT").shape == (3, 4)
        expected = data.reshape(3, 4) / 255
        assert np.allclose(net.output("I.OUTPUT"), expected)      # in init
        net.run(ticks=3)
        assert np.allclose(net.output("I.OUTPUT"), expected)
    finally:
        net.close()


def test_sequence_with_repeats_and_iterations(tmp_path):
    for i in range(2):
        np.full(4, 50 * (i + 1), np.uint8).tofile(tmp_path / f"f{i:02d}.raw")
    net = load(tmp_path, '<module class="InputRawImage" name="I" filename="f%02d.raw" '
                         'size_x="2" size_y="2" filecount="2" repeats="2" iterations="2"/>')
    try:
        got = []
        for _ in range(8):
            net.step()
            got.append(round(float(net.output("I.OUTPUT")[0, 0]) * 255))
        assert got == [50, 50, 100, 100, 50, 50, 100, 100]
        with pytest.raises(RunError, match="end_of_file"):
            net.step()
    finally:
        net.close()


def test_wrong_size_is_a_build_error_first_and_a_warning_later(tmp_path):
    np.zeros(5, np.uint8).tofile(tmp_path / "bad.raw")
    with pytest.raises(ModelError, match="has 5 bytes"):
        load(tmp_path, '<module class="InputRawImage" name="I" filename="bad.raw" '
                       'size_x="2" size_y="2"/>')
    with pytest.raises(ModelError, match="needs size_x and size_y"):
        load(tmp_path, '<module class="InputRawImage" name="I" filename="bad.raw"/>')
    np.full(4, 255, np.uint8).tofile(tmp_path / "s0.raw")
    np.zeros(3, np.uint8).tofile(tmp_path / "s1.raw")
    net = load(tmp_path, '<module class="InputRawImage" name="I" filename="s%d.raw" '
                         'size_x="2" size_y="2" filecount="2"/>')
    try:
        net.run(ticks=4)
        assert np.allclose(net.output("I.OUTPUT"), 1)          # s1 skipped: s0 stays
        assert len([e for e in net.log if e[1] == WARNING and "3 bytes" in e[3]]) == 1
    finally:
        net.close()
