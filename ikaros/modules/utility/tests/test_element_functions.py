"""Tests of Ikaros 3's element-wise functions of one input: Exp, Square, Negate, Invert, Not
and Clip (MODULES-V3 §3)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

DATA = [[0.0, -0.0, 1.5], [-2.0, 100.0, float("nan")]]


def _run(tmp_path, cls, attrs=""):
    net = load(tmp_path,
               f'<module class="Constant" name="C" data="0 -0 1.5; -2 100 nan"/>'
               f'<module class="{cls}" name="F" {attrs}/>'
               f'<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        net.step()
        out = net.output("F.OUTPUT").copy()
    finally:
        net.close()
    assert out.shape == (2, 3) and out.dtype == np.float32
    return out


x = np.array(DATA, np.float32)


@pytest.mark.parametrize("cls, expected", [
    ("Exp", [[1, 1, np.exp(np.float32(1.5))], [np.exp(np.float32(-2)), np.inf, np.nan]]),
    ("Square", [[0, 0, 2.25], [4, 10000, np.nan]]),
    ("Negate", [[-0.0, 0.0, -1.5], [2, -100, np.nan]]),
    ("Invert", [[np.inf, -np.inf, 1 / 1.5], [-0.5, 0.01, np.nan]]),
    ("Not", [[1, 1, 0], [0, 0, 0]]),
    ("Clip", [[0, 0, 1], [0, 1, np.nan]]),
])
def test_each_element(tmp_path, cls, expected):
    out = _run(tmp_path, cls)
    assert np.allclose(out, np.array(expected, np.float32), equal_nan=True, rtol=1e-6)


def test_negate_gives_minus_zero_for_zero(tmp_path):
    out = _run(tmp_path, "Negate")
    assert np.signbit(out[0, 0]) and not np.signbit(out[0, 1])


@pytest.mark.parametrize("attrs", ['a="-1" b="50"', 'a="50" b="-1"'])
def test_clip_limits_in_either_order(tmp_path, attrs):
    out = _run(tmp_path, "Clip", attrs)
    assert np.array_equal(out[:, :2], [[0, 0], [-1, 50]])
    assert out[0, 2] == 1.5
