"""Tests of the SelectMax module."""

import numpy as np

from ikaros.testing import load_body as load


def run(tmp_path, data, attrs=""):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="SelectMax" name="S" {attrs}/>'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.run(ticks=2)
        return net.output("S.OUTPUT")
    finally:
        net.close()


def test_one_hot_in_a_matrix(tmp_path):
    out = run(tmp_path, "1 2 3; 9 -1 4")
    assert out.shape == (2, 3) and out.dtype == np.float32
    assert np.array_equal(out, [[0, 0, 0], [1, 0, 0]])


def test_keep_value(tmp_path):
    assert np.array_equal(run(tmp_path, "-5 -2 -3", 'keep_value="yes"'), [0, -2, 0])


def test_ties_select_the_first(tmp_path):
    assert np.array_equal(run(tmp_path, "0 7 7 1"), [0, 1, 0, 0])
    assert np.array_equal(run(tmp_path, "0 0 0"), [1, 0, 0])


def test_random_input_over_several_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="4" outputsize_y="3" '
                         'seed="8"/>'
                         '<module class="SelectMax" name="S"/>'
                         '<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            r = net.output("R.OUTPUT")
            expected = (r == r.max()).astype(np.float32)
            assert np.array_equal(net.output("S.OUTPUT"), expected)
    finally:
        net.close()
