"""Tests of the TruncateArray module. Ikaros 2 takes the selection from the start of the input
whatever loop says, and position 0 gives 0 (golden-v2 TruncateArray)."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_ikaros2_example(tmp_path):
    body = ('<module class="Constant" name="A" data="1 2 3 4 5 6 7 8 9 10"/>\n'
            '<module class="TruncateArray" name="TA1" array_length="10" selection="4 6"/>\n'
            '<module class="TruncateArray" name="TA2" array_length="10" selection="4 6" '
            'loop="false"/>\n'
            '<module class="TruncateArray" name="TA3" array_length="10" selection="4 6"/>\n'
            '<connection source="A.OUTPUT" target="TA1.INPUT"/>\n'
            '<connection source="A.OUTPUT" target="TA2.INPUT"/>\n'
            '<connection source="A.OUTPUT" target="TA2.INPUT"/>\n'
            '<connection source="A.OUTPUT" target="TA2.INPUT"/>\n'
            '<connection source="A.OUTPUT" target="TA3.INPUT"/>\n'
            '<connection source="A.OUTPUT" target="TA3.INPUT"/>\n'
            '<connection source="A.OUTPUT" target="TA3.INPUT"/>\n')
    net = load(tmp_path, body)
    try:
        net.run(ticks=2)
        assert np.array_equal(net.output("TA1.OUTPUT"), [4, 6])
        assert np.array_equal(net.output("TA2.OUTPUT"), [4, 6])
        assert np.array_equal(net.output("TA3.OUTPUT"), [4, 6])    # loop is not used
    finally:
        net.close()


def test_selection_over_ticks_with_and_without_loop(tmp_path):
    body = ('<module class="Randomizer" name="R" outputsize="11" seed="2"/>\n'
            '<module class="TruncateArray" name="L" array_length="5" selection="5 1 1" '
            'honour_loop="yes"/>\n'
            '<module class="TruncateArray" name="N" array_length="5" selection="11 2" '
            'loop="no"/>\n'
            '<connection source="R.OUTPUT" target="L.INPUT" delay="0"/>\n'
            '<connection source="R.OUTPUT" target="N.INPUT" delay="0"/>\n')
    net = load(tmp_path, body)
    try:
        assert net.output("L.OUTPUT").shape == (2, 3)
        for _ in range(3):
            net.step()
            x = net.output("R.OUTPUT")
            assert np.array_equal(net.output("L.OUTPUT"), x[:10].reshape(2, 5)[:, [4, 0, 0]])
            assert np.array_equal(net.output("N.OUTPUT"), x[[10, 1]])
    finally:
        net.close()


def test_positions_outside_the_input_give_0_with_a_warning(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="0.5 -1 2 0.25 9"/>\n'
                         '<module class="TruncateArray" name="T" selection="0 1 6 5"/>\n'
                         '<connection source="A.OUTPUT" target="T.INPUT" delay="0"/>')
    with net:
        net.step()
        assert net.output("T.OUTPUT").tolist() == [0, 0.5, 0, 9]
        assert sum("give 0" in entry[3] for entry in net.log) == 1


def test_honour_loop_takes_the_selection_from_every_array(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2 3 4 5 6 7"/>\n'
                         '<module class="TruncateArray" name="T" array_length="3" '
                         'selection="1 2" honour_loop="yes"/>\n'
                         '<module class="TruncateArray" name="O" array_length="3" '
                         'selection="1 2"/>\n'
                         '<connection source="A.OUTPUT" target="T.INPUT" delay="0"/>\n'
                         '<connection source="A.OUTPUT" target="O.INPUT" delay="0"/>')
    with net:
        net.step()
        assert net.output("T.OUTPUT").tolist() == [[1, 2], [4, 5]]
        assert net.output("O.OUTPUT").tolist() == [1, 2]          # golden-v2 "loop"


@pytest.mark.parametrize("selection", ["1.5", ""])
def test_bad_selection_is_a_build_error(tmp_path, selection):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="A" data="1 2 3 4 5 6 7 8 9 10"/>\n'
                       f'<module class="TruncateArray" name="T" array_length="5" '
                       f'selection="{selection}"/>\n'
                       '<connection source="A.OUTPUT" target="T.INPUT"/>')
