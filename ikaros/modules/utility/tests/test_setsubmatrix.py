"""Tests of the SetSubmatrix module."""
import numpy as np

from ikaros.testing import load_body as load

BODY = ('<module class="Randomizer" name="S" outputsize_x="2" outputsize_y="2" seed="1"/>\n'
        '<module class="Randomizer" name="D" outputsize_x="4" outputsize_y="3" seed="2"/>\n'
        '<connection source="S.OUTPUT" target="M.SOURCE" delay="0"/>\n'
        '<connection source="D.OUTPUT" target="M.DESTINATION" delay="0"/>\n')


def expected(src, dst, ox, oy):
    out = dst.copy()
    for j in range(src.shape[0]):
        for i in range(src.shape[1]):
            if 0 <= j + oy < dst.shape[0] and 0 <= i + ox < dst.shape[1]:
                out[j + oy, i + ox] = src[j, i]
    return out


def test_writes_the_source_at_the_offset_over_ticks(tmp_path):
    net = load(tmp_path, BODY + '<module class="SetSubmatrix" name="M" offset_x="2" '
                                'offset_y="1"/>')
    try:
        assert net.output("M.OUTPUT").shape == (3, 4)
        for _ in range(3):
            net.step()
            src, dst = net.output("S.OUTPUT"), net.output("D.OUTPUT")
            assert np.array_equal(net.output("M.OUTPUT"), expected(src, dst, 2, 1))
        assert not [m for (_, level, where, m) in net.log if where == "M" and level == 5]
    finally:
        net.close()


def test_hand_worked_default_offset(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="S" data="9 8"/>\n'
                         '<module class="Constant" name="D" data="1 2 3; 4 5 6"/>\n'
                         '<module class="SetSubmatrix" name="M"/>\n'
                         '<connection source="S.OUTPUT" target="M.SOURCE" delay="0"/>\n'
                         '<connection source="D.OUTPUT" target="M.DESTINATION" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("M.OUTPUT"), [[9, 8, 3], [4, 5, 6]])
        net.set_parameter("M.offset_y", 1)
        net.set_parameter("M.offset_x", 1)
        net.step()
        assert np.array_equal(net.output("M.OUTPUT"), [[1, 2, 3], [4, 9, 8]])
    finally:
        net.close()


def test_parts_outside_are_clipped_with_one_warning(tmp_path):
    net = load(tmp_path, BODY + '<module class="SetSubmatrix" name="M" offset_x="3" '
                                'offset_y="-1"/>')
    try:
        for _ in range(3):
            net.step()
            src, dst = net.output("S.OUTPUT"), net.output("D.OUTPUT")
            assert np.array_equal(net.output("M.OUTPUT"), expected(src, dst, 3, -1))
        net.set_parameter("M.offset_x", 10)        # entirely outside: the destination
        net.step()
        assert np.array_equal(net.output("M.OUTPUT"), net.output("D.OUTPUT"))
        warnings = [m for (_, level, where, m) in net.log if where == "M" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()
