"""Tests of the TappedDelayLine module."""
import numpy as np

from ikaros.testing import load_body as load


def test_row_k_is_the_input_k_ticks_ago(tmp_path):
    body = ('<module class="Randomizer" name="R" outputsize="3" seed="1"/>\n'
            '<module class="TappedDelayLine" name="T" no_of_taps="4"/>\n'
            '<connection source="R.OUTPUT" target="T.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        assert net.output("T.OUTPUT").shape == (4, 3)
        assert not net.output("T.OUTPUT").any()
        history = []
        for _ in range(7):
            net.step()
            history.insert(0, net.output("R.OUTPUT"))
            expected = np.zeros((4, 3), dtype=np.float32)
            for k, x in enumerate(history[:4]):
                expected[k] = x
            assert np.array_equal(net.output("T.OUTPUT"), expected)
    finally:
        net.close()


def test_hand_worked_counter_through_a_matrix_input(tmp_path):
    # of a matrix input only the first row goes through the line (Ikaros 2 sizes OUTPUT by
    # INPUT's columns): a 2 x 2 Sweep gives 1, 2, 3, ... in every element from tick 0
    body = ('<module class="Sweep" name="S" outputsize_x="2" outputsize_y="2" min="0" '
            'max="100" step="1"/>\n'
            '<module class="TappedDelayLine" name="T" no_of_taps="3"/>\n'
            '<connection source="S.OUTPUT" target="T.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.run(ticks=2)
        assert np.array_equal(net.output("T.OUTPUT"), [[2, 2], [1, 1], [0, 0]])
        net.step()
        assert np.array_equal(net.output("T.OUTPUT"), [[3, 3], [2, 2], [1, 1]])
    finally:
        net.close()


def test_one_tap_is_the_input(tmp_path):
    body = ('<module class="Constant" name="C" data="4 5"/>\n'
            '<module class="TappedDelayLine" name="T" no_of_taps="1"/>\n'
            '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        assert np.array_equal(net.output("T.OUTPUT"), [[4, 5]])
    finally:
        net.close()
