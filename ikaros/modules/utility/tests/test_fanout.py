"""Tests of the FanOut module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_splits_cells_row_by_row(tmp_path):
    data = np.arange(24, dtype=np.float32).reshape(4, 6)
    text = "; ".join(" ".join(str(int(v)) for v in row) for row in data)
    net = load(tmp_path, f'<module class="Constant" name="C" data="{text}"/>'
               '<module class="FanOut" name="F" outputs="6" cell_size_x="3" cell_size_y="2"/>'
               '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        for _ in range(3):
            net.step()
            for k in range(6):
                r, c = divmod(k, 3)
                got = net.output(f"F.OUTPUT{k + 1}")
                assert got.shape == (2, 2)
                assert np.array_equal(got, data[r::2, c::3]), k
        # hand-worked: position 5 (row 1, column 1 of each cell)
        assert np.array_equal(net.output("F.OUTPUT5"), [[7, 10], [19, 22]])
    finally:
        net.close()


def test_one_dimensional_input_and_partial_cells(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2 3 4 5 6 7"/>'
               '<module class="FanOut" name="F" outputs="2" cell_size_x="2"/>'
               '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("F.OUTPUT1"), [1, 3, 5])    # 7 is a partial cell
        assert np.array_equal(net.output("F.OUTPUT2"), [2, 4, 6])
    finally:
        net.close()


def test_fewer_or_more_outputs_than_positions(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2 3 4"/>'
               '<module class="FanOut" name="F" outputs="3" cell_size_x="2"/>'
               '<module class="FanOut" name="G" outputs="1" cell_size_x="2"/>'
               '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="G.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("F.OUTPUT1"), [1, 3])
        assert np.array_equal(net.output("F.OUTPUT2"), [2, 4])
        assert np.array_equal(net.output("F.OUTPUT3"), [0, 0])
        assert np.array_equal(net.output("G.OUTPUT1"), [1, 3])
        assert sum("positions" in entry[3] for entry in net.log) == 2
    finally:
        net.close()


def test_follows_a_changing_input(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" outputsize_x="2" outputsize_y="2" '
               'min="0" max="10" step="1"/>'
               '<module class="FanOut" name="F" outputs="4" cell_size_x="2" cell_size_y="2"/>'
               '<connection source="S.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        for tick in range(4):
            net.step()
            for k in range(4):
                assert net.output(f"F.OUTPUT{k + 1}").shape == (1, 1)
                assert net.output(f"F.OUTPUT{k + 1}")[0, 0] == tick + 1
    finally:
        net.close()


def test_input_smaller_than_a_cell_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="C" data="1"/>'
             '<module class="FanOut" name="F" outputs="2" cell_size_x="2"/>'
             '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
