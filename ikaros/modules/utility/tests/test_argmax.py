"""Tests of the ArgMax module."""
import numpy as np

from ikaros.testing import load_body as load


def _argmax(body, tmp_path, ticks=1):
    net = load(tmp_path, body + '\n<module class="ArgMax" name="M"/>\n'
               '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.run(ticks=ticks)
        return net.output("M.OUTPUT").copy(), net.output("M.VALUE").copy()
    finally:
        net.close()


def test_matrix_gives_column_then_row(tmp_path):
    out, value = _argmax('<module class="Constant" name="C" data="1 2 3; 4 9 6; 0 0 0"/>',
                         tmp_path)
    assert np.array_equal(out, [1, 1]) and value[0] == 9


def test_vector_gives_index_and_zero(tmp_path):
    out, value = _argmax('<module class="Constant" name="C" data="-5 -1 -3 -2"/>', tmp_path)
    assert np.array_equal(out, [1, 0]) and value[0] == -1


def test_ties_pick_the_first_row_by_row(tmp_path):
    out, value = _argmax('<module class="Constant" name="C" data="0 7; 7 7"/>', tmp_path)
    assert np.array_equal(out, [1, 0]) and value[0] == 7


def test_moving_maximum(tmp_path):
    # A 3x4 random matrix that changes every tick; compare with numpy's argmax.
    net = load(tmp_path,
               '<module class="Randomizer" name="R" outputsize_x="4" outputsize_y="3" '
               'seed="5"/>\n<module class="ArgMax" name="M"/>\n'
               '<connection source="R.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        for _ in range(6):
            net.step()
            r = net.output("R.OUTPUT")
            row, col = np.unravel_index(np.argmax(r), r.shape)
            assert np.array_equal(net.output("M.OUTPUT"), [col, row])
            assert net.output("M.VALUE")[0] == r.max()
    finally:
        net.close()
