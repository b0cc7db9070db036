"""Tests of Ikaros 3's element-wise combinations of two inputs: And, Or, Xor, Maximum and
Minimum (MODULES-V3 §4)."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load

A = "0 1 -2; 0 nan 3"
B = "0 0 5; 7 1 nan"


def _run(tmp_path, cls, a=A, b=B):
    net = load(tmp_path,
               f'<module class="Constant" name="A" data="{a}"/>'
               f'<module class="Constant" name="B" data="{b}"/>'
               f'<module class="{cls}" name="F"/>'
               f'<connection source="A.OUTPUT" target="F.INPUT1" delay="0"/>'
               f'<connection source="B.OUTPUT" target="F.INPUT2" delay="0"/>')
    try:
        net.step()
        return net.output("F.OUTPUT").copy()
    finally:
        net.close()


@pytest.mark.parametrize("cls, expected", [
    # non-zero (negative and NaN included) is true
    ("And", [[0, 0, 1], [0, 1, 1]]),
    ("Or", [[0, 1, 1], [1, 1, 1]]),
    ("Xor", [[0, 1, 0], [1, 0, 0]]),
    # std::max(a, b) / std::min(a, b): NaN in b gives a, NaN in a gives NaN
    ("Maximum", [[0, 1, 5], [7, np.nan, 3]]),
    ("Minimum", [[0, 0, -2], [0, np.nan, 3]]),
])
def test_each_element(tmp_path, cls, expected):
    out = _run(tmp_path, cls)
    assert out.shape == (2, 3) and out.dtype == np.float32
    assert np.array_equal(out, np.array(expected, np.float32), equal_nan=True)


def test_shapes_must_match_exactly(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same shape"):
        _run(tmp_path, "And", a="1 2 3 4", b="1 2; 3 4")


def test_input2_is_required(tmp_path):
    with pytest.raises(ikaros.ModelError, match="INPUT2"):
        load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
                       '<module class="Or" name="F"/>'
                       '<connection source="A.OUTPUT" target="F.INPUT1" delay="0"/>')
