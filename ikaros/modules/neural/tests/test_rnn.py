"""Tests of the RNN template module."""
import numpy as np

from ikaros.testing import load_body as load


def test_copies_input_to_output_and_state_stays_0(tmp_path):
    # Ikaros 2 (golden-v2 RNN): STATE-OUT is never written
    net = load(tmp_path,
               '<module class="Sweep" name="S" outputsize_x="3" outputsize_y="2" step="0.25"/>'
               '<module class="Constant" name="C" data="5 6 7; 8 9 10"/>'
               '<module class="RNN" name="R"/>'
               '<connection source="S.OUTPUT" target="R.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="R.T-INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="R.TOP-DOWN" delay="0"/>')
    try:
        assert net.output("R.OUTPUT").shape == (2, 3)
        assert net.output("R.STATE-OUT").shape == (2, 3)
        for tick in range(6):
            net.step()
            expected = np.full((2, 3), ((tick + 1) % 5) * 0.25, np.float32)
            assert np.array_equal(net.output("R.OUTPUT"), expected)
            assert np.array_equal(net.output("R.STATE-OUT"), np.zeros((2, 3)))
    finally:
        net.close()


def test_optional_inputs_may_stay_unconnected(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 -2 3"/>'
                         '<module class="RNN" name="R"/>'
                         '<connection source="C.OUTPUT" target="R.INPUT"/>')
    try:
        assert np.array_equal(net.output("R.OUTPUT"), [0, 0, 0])
        net.step()                                   # delay 1: tick 0 sees C's init value
        assert np.array_equal(net.output("R.OUTPUT"), [1, -2, 3])
        assert np.array_equal(net.output("R.STATE-OUT"), [0, 0, 0])
    finally:
        net.close()
