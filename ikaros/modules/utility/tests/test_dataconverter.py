"""Tests of the DataConverter module."""
import numpy as np

from ikaros.module import WARNING
from ikaros.testing import load_body as load


def _load(tmp_path, data, x, y):
    return load(tmp_path,
                f'<module class="Constant" name="C" data="{data}"/>\n'
                f'<module class="DataConverter" name="D" output_size_x="{x}" '
                f'output_size_y="{y}"/>\n'
                '<connection source="C.OUTPUT" target="D.INPUT" delay="0"/>')


def test_reshapes_row_by_row(tmp_path):
    net = _load(tmp_path, "1 2 3 4 5 6", 3, 2)
    try:
        net.run(ticks=2)
        assert np.array_equal(net.output("D.OUTPUT"), [[1, 2, 3], [4, 5, 6]])
        assert not [e for e in net.log if e[1] == WARNING]
    finally:
        net.close()


def test_default_size_is_4_by_4(tmp_path):
    net = load(tmp_path,
               '<module class="Randomizer" name="R" outputsize="16" seed="1"/>\n'
               '<module class="DataConverter" name="D"/>\n'
               '<connection source="R.OUTPUT" target="D.INPUT" delay="0"/>')
    try:
        for _ in range(3):
            net.step()
            assert np.array_equal(net.output("D.OUTPUT"),
                                  net.output("R.OUTPUT").reshape(4, 4))
    finally:
        net.close()


def test_smaller_input_is_padded_and_larger_truncated_with_a_warning(tmp_path):
    net = _load(tmp_path, "1 2 3", 2, 2)
    try:
        net.step()
        assert np.array_equal(net.output("D.OUTPUT"), [[1, 2], [3, 0]])
        assert len([e for e in net.log if e[1] == WARNING]) == 1
    finally:
        net.close()
    (tmp_path / "b").mkdir()
    net = _load(tmp_path / "b", "1 2 3 4 5", 2, 2)
    try:
        net.step()
        assert np.array_equal(net.output("D.OUTPUT"), [[1, 2], [3, 4]])
    finally:
        net.close()
