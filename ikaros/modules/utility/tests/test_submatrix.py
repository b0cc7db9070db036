"""Tests of the Submatrix module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load

RANDOM = ('<module class="Randomizer" name="R" outputsize_x="6" outputsize_y="5" seed="4"/>\n'
          '<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>\n')


def test_region_over_ticks(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="Submatrix" name="S" x0="1" x1="4" y0="2" '
                                  'y1="5"/>')
    try:
        assert net.output("S.OUTPUT").shape == (3, 3)
        for _ in range(3):
            net.step()
            assert np.array_equal(net.output("S.OUTPUT"), net.output("R.OUTPUT")[2:5, 1:4])
    finally:
        net.close()


def test_ikaros2_example(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" outputsize_x="3" outputsize_y="3" '
                         'data="1 2 3 2 3 4 3 4 5"/>\n'
                         '<module class="Submatrix" name="S" x0="1" x1="3" y0="1" y1="2"/>\n'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), [[3, 4]])
    finally:
        net.close()


def test_kernel_size_and_defaults(tmp_path):
    body = RANDOM + ('<module class="Submatrix" name="S" kernel_size="5"/>\n'
                     '<module class="Submatrix" name="W"/>\n'
                     '<connection source="R.OUTPUT" target="W.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        assert net.output("S.OUTPUT").shape == (1, 2)
        net.step()
        x = net.output("R.OUTPUT")
        assert np.array_equal(net.output("S.OUTPUT"), x[2:3, 2:4])
        assert np.array_equal(net.output("W.OUTPUT"), x)
    finally:
        net.close()


def test_1d_input(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2 3 4 5"/>\n'
                         '<module class="Submatrix" name="S" x0="1" x1="3"/>\n'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), [2, 3])
    finally:
        net.close()


def shifted(region, dx, dy):
    out = np.zeros_like(region)
    rows, cols = region.shape
    for j in range(rows):
        for i in range(cols):
            if 0 <= j + dy < rows and 0 <= i + dx < cols:
                out[j, i] = region[j + dy, i + dx]
    return out


def test_shift(tmp_path):
    body = RANDOM + ('<module class="Constant" name="K" data="1 -2"/>\n'
                     '<module class="Submatrix" name="S" x0="1" y1="4" offset_x="0.5" '
                     'direction="-1"/>\n'
                     '<connection source="K.OUTPUT" target="S.SHIFT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        for _ in range(3):
            net.step()
            region = net.output("R.OUTPUT")[0:4, 1:6]
            # dx = int(0.5 - 1) = 0 (toward 0), dy = int(0 + 2) = 2
            assert np.array_equal(net.output("S.OUTPUT"), shifted(region, 0, 2))
        net.set_parameter("S.direction", 2)          # dx = int(2.5) = 2, dy = -4
        net.step()
        region = net.output("R.OUTPUT")[0:4, 1:6]
        assert np.array_equal(net.output("S.OUTPUT"), shifted(region, 2, -4))
        assert not net.output("S.OUTPUT").any()      # shifted entirely out
    finally:
        net.close()


def test_bad_range_is_a_build_error(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, RANDOM + '<module class="Submatrix" name="S" x0="4" x1="2"/>')
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, RANDOM + '<module class="Submatrix" name="S" y1="9"/>')
