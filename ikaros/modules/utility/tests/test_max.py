"""Tests of the Max module."""

import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_hand_worked(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 -5; 3 0"/>'
                         '<module class="Constant" name="B" data="2 -6; 3 -1"/>'
                         '<module class="Max" name="M"/>'
                         '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>'
                         '<connection source="B.OUTPUT" target="M.INPUT2" delay="0"/>')
    try:
        net.step()
        out = net.output("M.OUTPUT")
        assert out.shape == (2, 2) and out.dtype == np.float32
        assert np.array_equal(out, [[2, -5], [3, 0]])
    finally:
        net.close()


def test_random_inputs_over_several_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="A" outputsize="6" min="-1" seed="1"/>'
                         '<module class="Randomizer" name="B" outputsize="6" min="-1" seed="2"/>'
                         '<module class="Max" name="M"/>'
                         '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>'
                         '<connection source="B.OUTPUT" target="M.INPUT2" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            a, b = net.output("A.OUTPUT"), net.output("B.OUTPUT")
            assert np.array_equal(net.output("M.OUTPUT"), np.where(a > b, a, b))
    finally:
        net.close()


def test_inputs_of_different_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same size"):
        load(tmp_path, '<module class="Constant" name="A" data="1 2 3"/>'
                       '<module class="Constant" name="B" data="1 2"/>'
                       '<module class="Max" name="M"/>'
                       '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>'
                       '<connection source="B.OUTPUT" target="M.INPUT2" delay="0"/>')


def _reduce(tmp_path, cls, data):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="{cls}" name="M"/>'
                         '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.step()
        return net.output("M.OUTPUT").copy()
    finally:
        net.close()


@pytest.mark.parametrize("cls, expected", [("Max", 4), ("Min", -7)])
def test_ikaros_3_input_is_a_reduction(tmp_path, cls, expected):
    # the Ikaros 3 interface: one INPUT, one value out (MODULES-V3 §5); NaN is skipped
    out = _reduce(tmp_path, cls, "3 nan; 4 -7")
    assert out.shape == (1,) and out[0] == expected


@pytest.mark.parametrize("cls, expected", [("Max", -np.inf), ("Min", np.inf)])
def test_an_all_nan_input_gives_the_starting_value(tmp_path, cls, expected):
    assert _reduce(tmp_path, cls, "nan nan")[0] == expected


def test_both_interfaces_at_once_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="not both"):
        load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
                       '<module class="Max" name="M"/>'
                       '<connection source="A.OUTPUT" target="M.INPUT" delay="0"/>'
                       '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>'
                       '<connection source="A.OUTPUT" target="M.INPUT2" delay="0"/>')


def test_one_ikaros_2_input_alone_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="INPUT1 and INPUT2 must both be connected"):
        load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
                       '<module class="Max" name="M"/>'
                       '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>')
