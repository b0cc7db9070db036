"""Tests of the Select module."""

import numpy as np
import pytest

import ikaros
from ikaros.module import WARNING
from ikaros.testing import load_body as load


def run(tmp_path, data, select, ticks=2):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="Select" name="S" select="{select}"/>'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.run(ticks=ticks)
        return net.output("S.OUTPUT"), [e for e in net.log if e[1] == WARNING]
    finally:
        net.close()


def test_indices_into_an_array(tmp_path):
    out, warnings = run(tmp_path, "10 11 12 13 14", "3 2 1 3")
    assert out.shape == (4,) and out.dtype == np.float32
    assert np.array_equal(out, [13, 12, 11, 13])
    assert not warnings


def test_xy_pairs_into_a_matrix(tmp_path):
    out, _ = run(tmp_path, "0 1 2 3 4; 5 6 7 8 9; 10 11 12 13 14", "3 0; 2 1; 1 2; 4 2")
    assert np.array_equal(out, [3, 7, 11, 14])          # INPUT[y][x]


def test_flat_indices_into_a_matrix(tmp_path):
    out, _ = run(tmp_path, "0 1 2; 3 4 5", "5 0 4")
    assert np.array_equal(out, [5, 0, 4])


def test_out_of_range_gives_zero_and_one_warning(tmp_path):
    out, warnings = run(tmp_path, "1 2 3", "2 3 -1 0", ticks=3)
    assert np.array_equal(out, [3, 0, 0, 1])
    assert len(warnings) == 1
    out, warnings = run(tmp_path, "1 2; 3 4", "1 1; 2 0; 0 2")
    assert np.array_equal(out, [4, 0, 0])
    assert len(warnings) == 1


def test_follows_a_changing_input(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="4" outputsize_y="3" '
                         'seed="2"/>'
                         '<module class="Select" name="S" select="0 0; 3 2; 1 1"/>'
                         '<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        for _ in range(3):
            net.step()
            r = net.output("R.OUTPUT")
            assert np.array_equal(net.output("S.OUTPUT"), [r[0, 0], r[2, 3], r[1, 1]])
    finally:
        net.close()


def test_no_selection_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="select"):
        load(tmp_path, '<module class="Constant" name="C" data="1 2"/>'
                       '<module class="Select" name="S"/>'
                       '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
