"""Tests of the SumMatrix module."""
import numpy as np

from ikaros.testing import load_body as load

BODY = ('<module class="Randomizer" name="R" outputsize_x="4" outputsize_y="3" min="-1" '
        'seed="9"/>\n'
        '<module class="SumMatrix" name="A"/>\n'
        '<module class="SumMatrix" name="C" direction="column"/>\n'
        '<module class="SumMatrix" name="W" direction="row"/>\n'
        '<connection source="R.OUTPUT" target="A.INPUT" delay="0"/>\n'
        '<connection source="R.OUTPUT" target="C.INPUT" delay="0"/>\n'
        '<connection source="R.OUTPUT" target="W.INPUT" delay="0"/>\n')


def test_all_column_and_row_sums_over_ticks(tmp_path):
    net = load(tmp_path, BODY)
    try:
        assert net.output("A.OUTPUT").shape == (1,)
        assert net.output("C.OUTPUT").shape == (4,)      # one per column
        assert net.output("W.OUTPUT").shape == (3,)      # one per row
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            assert np.allclose(net.output("A.OUTPUT"), [x.sum()], atol=1e-5)
            assert np.allclose(net.output("C.OUTPUT"), x.sum(axis=0), atol=1e-5)
            assert np.allclose(net.output("W.OUTPUT"), x.sum(axis=1), atol=1e-5)
    finally:
        net.close()


def test_hand_worked_non_square_and_1d(tmp_path):
    body = ('<module class="Constant" name="M" data="1 2 3; 4 5 6"/>\n'
            '<module class="Constant" name="V" data="1 2 3"/>\n'
            '<module class="SumMatrix" name="A"/>\n'
            '<module class="SumMatrix" name="C" direction="column"/>\n'
            '<module class="SumMatrix" name="W" direction="row"/>\n'
            '<module class="SumMatrix" name="V1" direction="row"/>\n'
            '<module class="SumMatrix" name="V2" direction="column"/>\n'
            '<connection source="M.OUTPUT" target="A.INPUT" delay="0"/>\n'
            '<connection source="M.OUTPUT" target="C.INPUT" delay="0"/>\n'
            '<connection source="M.OUTPUT" target="W.INPUT" delay="0"/>\n'
            '<connection source="V.OUTPUT" target="V1.INPUT" delay="0"/>\n'
            '<connection source="V.OUTPUT" target="V2.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        assert np.array_equal(net.output("A.OUTPUT"), [21])
        assert np.array_equal(net.output("C.OUTPUT"), [5, 7, 9])
        assert np.array_equal(net.output("W.OUTPUT"), [6, 15])
        assert np.array_equal(net.output("V1.OUTPUT"), [6])
        assert np.array_equal(net.output("V2.OUTPUT"), [1, 2, 3])
    finally:
        net.close()
