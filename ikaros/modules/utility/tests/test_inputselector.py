"""Tests of the InputSelector module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_select_picks_the_input_zero_based(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2; 3 4"/>'
               '<module class="Constant" name="B" data="5 6; 7 8"/>'
               '<module class="Constant" name="Cc" data="9 10; 11 12"/>'
               '<module class="Sweep" name="S" min="0" max="2" step="1"/>'
               '<module class="InputSelector" name="I" inputs="3"/>'
               '<connection source="A.OUTPUT" target="I.INPUT1" delay="0"/>'
               '<connection source="B.OUTPUT" target="I.INPUT2" delay="0"/>'
               '<connection source="Cc.OUTPUT" target="I.INPUT3" delay="0"/>'
               '<connection source="S.OUTPUT" target="I.SELECT" delay="0"/>')
    try:
        inputs = [np.array([[1, 2], [3, 4]]), np.array([[5, 6], [7, 8]]),
                  np.array([[9, 10], [11, 12]])]
        for tick in range(6):                  # S: 1, 2, 0, 1, 2, 0
            net.step()
            assert np.array_equal(net.output("I.OUTPUT"), inputs[(tick + 1) % 3])
    finally:
        net.close()


def test_single_input_is_named_input(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2 3"/>'
               '<module class="Constant" name="Z" data="0"/>'
               '<module class="InputSelector" name="I" inputs="1"/>'
               '<connection source="A.OUTPUT" target="I.INPUT" delay="0"/>'
               '<connection source="Z.OUTPUT" target="I.SELECT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("I.OUTPUT"), [1, 2, 3])
    finally:
        net.close()


def test_out_of_range_select_gives_zero_and_one_warning(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
               '<module class="Constant" name="B" data="3 4"/>'
               '<module class="Constant" name="S" data="2"/>'
               '<module class="InputSelector" name="I"/>'
               '<connection source="A.OUTPUT" target="I.INPUT1" delay="0"/>'
               '<connection source="B.OUTPUT" target="I.INPUT2" delay="0"/>'
               '<connection source="S.OUTPUT" target="I.SELECT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("I.OUTPUT"), [0, 0])
        assert sum("not an input index" in entry[3] for entry in net.log) == 1
        net.set_parameter("S.data", "-1")
        net.step()
        assert np.array_equal(net.output("I.OUTPUT"), [0, 0])
        net.set_parameter("S.data", "0.9")          # rounds to 1
        net.step()
        assert np.array_equal(net.output("I.OUTPUT"), [3, 4])
    finally:
        net.close()


def test_inputs_of_different_shapes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same shape"):
        load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
             '<module class="Constant" name="B" data="3 4 5"/>'
             '<module class="Constant" name="S" data="0"/>'
             '<module class="InputSelector" name="I"/>'
             '<connection source="A.OUTPUT" target="I.INPUT1"/>'
             '<connection source="B.OUTPUT" target="I.INPUT2"/>'
             '<connection source="S.OUTPUT" target="I.SELECT"/>')
