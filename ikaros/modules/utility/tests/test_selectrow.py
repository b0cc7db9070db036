"""Tests of the SelectRow module."""
import numpy as np

from ikaros.testing import load_body as load

RANDOM = ('<module class="Randomizer" name="R" outputsize_x="4" outputsize_y="3" min="-1" '
          'max="1" seed="7"/>\n<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>\n')


def test_selects_the_row_on_every_tick(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="SelectRow" name="S" selected_row="2"/>')
    try:
        assert net.output("S.OUTPUT").shape == (4,)
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT")
            assert np.array_equal(net.output("S.OUTPUT"), x[2])
    finally:
        net.close()


def test_default_row_is_0_and_the_row_can_change(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="SelectRow" name="S"/>')
    try:
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), net.output("R.OUTPUT")[0])
        net.set_parameter("S.selected_row", 1)
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), net.output("R.OUTPUT")[1])
    finally:
        net.close()


def test_row_outside_the_matrix_gives_zero_and_one_warning(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="SelectRow" name="S" selected_row="3"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("S.OUTPUT"), np.zeros(4))
        warnings = [m for (_, level, where, m) in net.log if where == "S" and level == 5]
        assert len(warnings) == 1
        net.set_parameter("S.selected_row", -1)
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), np.zeros(4))
    finally:
        net.close()


def test_a_1d_input_is_one_row(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="5 6 7"/>\n'
                         '<module class="SelectRow" name="S"/>\n'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), [5, 6, 7])
    finally:
        net.close()
