"""Tests of the Flip module."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

M = np.array([[1, 2, 3], [4, 5, 6]], dtype=np.float32)
DATA = "1 2 3; 4 5 6"


@pytest.mark.parametrize("kind, expected", [
    ("none", [[1, 2, 3], [4, 5, 6]]),
    ("up-down", [[4, 5, 6], [1, 2, 3]]),
    ("left-right", [[3, 2, 1], [6, 5, 4]]),
    ("rotate-left", [[3, 6], [2, 5], [1, 4]]),       # counterclockwise
    ("rotate-right", [[4, 1], [5, 2], [6, 3]]),      # clockwise
    ("rotate-180", [[6, 5, 4], [3, 2, 1]]),
])
def test_each_type_hand_worked(tmp_path, kind, expected):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{DATA}"/>'
               f'<module class="Flip" name="F" type="{kind}"/>'
               '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        for _ in range(2):
            net.step()
            assert np.array_equal(net.output("F.OUTPUT"), expected)
    finally:
        net.close()


def test_default_is_up_down_and_follows_the_input(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="4" '
               'outputsize_y="3" seed="2"/>'
               '<module class="Flip" name="F"/>'
               '<connection source="R.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        for _ in range(3):
            net.step()
            assert np.array_equal(net.output("F.OUTPUT"), np.flipud(net.output("R.OUTPUT")))
    finally:
        net.close()


def test_one_dimensional_input(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2 3"/>'
               '<module class="Flip" name="U"/>'
               '<module class="Flip" name="L" type="left-right"/>'
               '<module class="Flip" name="R" type="rotate-right"/>'
               '<connection source="C.OUTPUT" target="U.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="R.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("U.OUTPUT"), [1, 2, 3])    # one row: no change
        assert np.array_equal(net.output("L.OUTPUT"), [3, 2, 1])
        assert np.array_equal(net.output("R.OUTPUT"), [[1], [2], [3]])
    finally:
        net.close()


def test_type_change_that_does_not_fit_keeps_the_build_type(tmp_path):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{DATA}"/>'
               '<module class="Flip" name="F" type="up-down"/>'
               '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        net.set_parameter("F.type", "rotate-180")
        net.step()
        assert np.array_equal(net.output("F.OUTPUT"), np.rot90(M, 2))
        net.set_parameter("F.type", "rotate-left")      # would need a 3 x 2 output
        net.step()
        assert np.array_equal(net.output("F.OUTPUT"), np.flipud(M))
        assert any("does not fit" in entry[3] for entry in net.log)
    finally:
        net.close()
