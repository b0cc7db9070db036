"""Tests of the Distance module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def _load(tmp_path, a, b, kind="euclidean"):
    return load(tmp_path,
                f'<module class="Constant" name="A" data="{a}"/>\n'
                f'<module class="Constant" name="B" data="{b}"/>\n'
                f'<module class="Distance" name="D" type="{kind}"/>\n'
                '<connection source="A.OUTPUT" target="D.INPUT1" delay="0"/>\n'
                '<connection source="B.OUTPUT" target="D.INPUT2" delay="0"/>')


def test_euclidean(tmp_path):
    net = _load(tmp_path, "0 0", "3 4")
    try:
        net.step()
        assert net.output("D.OUTPUT").shape == (1,)
        assert net.output("D.OUTPUT")[0] == 5
    finally:
        net.close()


def test_cityblock(tmp_path):
    net = _load(tmp_path, "1 -2 3", "-1 2 3", "cityblock")
    try:
        net.step()
        assert net.output("D.OUTPUT")[0] == 6
    finally:
        net.close()


def test_shapes_are_ignored_and_distance_follows_the_input(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="S" min="0" max="100" step="1" '
               'outputsize_x="2" outputsize_y="2"/>\n'
               '<module class="Constant" name="B" data="1 2 3 4"/>\n'
               '<module class="Distance" name="D"/>\n'
               '<connection source="S.OUTPUT" target="D.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="D.INPUT2" delay="0"/>')
    try:
        for tick in range(4):
            net.step()
            expected = np.linalg.norm(np.full(4, tick + 1.0) - [1, 2, 3, 4])
            assert np.isclose(net.output("D.OUTPUT")[0], expected)
    finally:
        net.close()


def test_different_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same size"):
        _load(tmp_path, "1 2", "1 2 3")
