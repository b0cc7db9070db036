"""Tests of Ikaros 3's element-wise combinations of two inputs: And, Or, Xor, Maximum and
Minimum (MODULES-V3 §4), in Ikaros 3 files; and of Ikaros 2's scalar And, Or and Xor
(issue 35: the original's first elements against threshold, high / low and INVERSE)."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load

A = "0 1 -2; 0 nan 3"
B = "0 0 5; 7 1 nan"


def _net(tmp_path, cls, a=A, b=B, attrs="", dialect="3"):
    return load(tmp_path,
                f'<module class="Constant" name="A" data="{a}"/>'
                f'<module class="Constant" name="B" data="{b}"/>'
                f'<module class="{cls}" name="F" {attrs}/>'
                f'<connection source="A.OUTPUT" target="F.INPUT1" delay="0"/>'
                f'<connection source="B.OUTPUT" target="F.INPUT2" delay="0"/>',
                dialect=dialect)


def _run(tmp_path, cls, a=A, b=B):
    net = _net(tmp_path, cls, a, b)
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
                       '<connection source="A.OUTPUT" target="F.INPUT1" delay="0"/>',
             dialect="3")


TRUTH = {"And": np.logical_and, "Or": np.logical_or, "Xor": np.logical_xor}


@pytest.mark.parametrize("cls", ["And", "Or", "Xor"])
@pytest.mark.parametrize("a, b, threshold, high, low", [
    ("0.8 5", "0.9; 7", 0.5, 2.0, -1.0),      # only the first elements count
    ("0.3", "0.05", 0.1, 1.0, 0.0),
    ("1 1 1", "0", 0.5, 1.0, 0.0),
    ("0.5", "0.6", 0.5, 3.0, 0.25),          # 0.5 is not above 0.5
    ("-2", "0.7", 0.5, 1.0, 0.0),
    ("0.7", "-0.3", 0.5, 1.0, 0.0),
])
def test_ikaros_2_compares_the_first_elements_with_the_threshold(tmp_path, cls, a, b,
                                                                 threshold, high, low):
    net = _net(tmp_path, cls, a, b, f'threshold="{threshold}" high="{high}" low="{low}"',
               dialect="2")
    with net:
        net.step()
        first_a, first_b = float(a.split()[0]), float(b.split()[0].rstrip(";"))
        # Xor compares INPUT2 with 0 in Ikaros 2 (the golden files show it)
        threshold_b = 0.0 if cls == "Xor" else threshold
        true = TRUTH[cls](np.float32(first_a) > np.float32(threshold),
                          np.float32(first_b) > np.float32(threshold_b))
        assert net.output("F.OUTPUT").tolist() == [high if true else low]
        assert net.output("F.INVERSE").tolist() == [low if true else high]


def test_ikaros_2_xor_compares_input2_with_the_threshold_on_request(tmp_path):
    for option, want in (("zero", 0.0), ("threshold", 1.0)):
        with _net(tmp_path, "Xor", "0.3", "0.05", f'threshold="0.1" '
                  f'input2_threshold="{option}"', dialect="2") as net:
            net.step()
            assert net.output("F.OUTPUT").tolist() == [want]


def test_ikaros_3_has_no_inverse(tmp_path):
    with _net(tmp_path, "And", "1 0", "1 1") as net:
        net.step()
        assert net.output("F.OUTPUT").tolist() == [1, 0]
        with pytest.raises(KeyError):
            net.output("F.INVERSE")
