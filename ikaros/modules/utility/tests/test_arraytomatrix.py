"""Tests of the ArrayToMatrix module."""
import numpy as np

from ikaros.testing import load_body as load


def _load(tmp_path, data, length):
    return load(tmp_path,
                f'<module class="Constant" name="C" data="{data}"/>\n'
                f'<module class="ArrayToMatrix" name="A" array_length="{length}"/>\n'
                '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>')


def test_exact_multiple(tmp_path):
    net = _load(tmp_path, "1 2 3 4 5 6", 3)
    try:
        net.step()
        assert np.array_equal(net.output("A.OUTPUT"), [[1, 2, 3], [4, 5, 6]])
    finally:
        net.close()


def test_last_row_is_padded_with_zeros(tmp_path):
    net = _load(tmp_path, "1 2 3 4 5", 2)
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("A.OUTPUT"), [[1, 2], [3, 4], [5, 0]])
    finally:
        net.close()


def test_matrix_input_is_read_row_by_row(tmp_path):
    net = _load(tmp_path, "1 2; 3 4", 4)
    try:
        net.step()
        assert np.array_equal(net.output("A.OUTPUT"), [[1, 2, 3, 4]])
    finally:
        net.close()


def test_follows_the_input(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="S" min="0" max="100" step="1" outputsize="4"/>\n'
               '<module class="ArrayToMatrix" name="A" array_length="2"/>\n'
               '<connection source="S.OUTPUT" target="A.INPUT" delay="0"/>')
    try:
        for tick in range(4):
            net.step()
            assert np.array_equal(net.output("A.OUTPUT"), np.full((2, 2), tick + 1))
    finally:
        net.close()
