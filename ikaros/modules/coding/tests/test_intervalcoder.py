"""Tests of the IntervalCoder module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def code(x, n, r, lo, hi):
    """Units a .. a + 2r, a the value's position rounded to whole steps (a value half-way
    between two steps does not occur in these tests)."""
    step = (hi - lo) / (n - 2 * r - 1)
    a = np.floor((x - lo) / step + 0.5)
    out = np.zeros(n)
    for i in range(n):
        if a <= i <= a + 2 * r:
            out[i] = 1 / (1 + 2 * r)
    return out


def test_code_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" min="-2" max="3" seed="1"/>\n'
                         '<module class="IntervalCoder" name="C" outputsize="12" radius="2" '
                         'min="-2" max="3"/>\n'
                         '<connection source="R.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        for _ in range(5):
            net.step()
            x = float(net.output("R.OUTPUT")[0])
            y = net.output("C.OUTPUT")
            assert np.allclose(y, code(x, 12, 2, -2, 3), atol=1e-7)
            assert np.isclose(y.sum(), 1)
    finally:
        net.close()


def test_hand_worked_ends(tmp_path):
    # 10 units, radius 1: step = 1/7; 0 -> units 0..2, 1 -> units 7..9, 0.5 -> 3.5 steps,
    # a hair below in single precision (the golden files show it): units 3..5
    body = ('<module class="Constant" name="K" data="0"/>\n'
            '<module class="Constant" name="L" data="1"/>\n'
            '<module class="Constant" name="M" data="0.5"/>\n'
            '<module class="IntervalCoder" name="A"/>\n'
            '<module class="IntervalCoder" name="B"/>\n'
            '<module class="IntervalCoder" name="C"/>\n'
            '<connection source="K.OUTPUT" target="A.INPUT" delay="0"/>\n'
            '<connection source="L.OUTPUT" target="B.INPUT" delay="0"/>\n'
            '<connection source="M.OUTPUT" target="C.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        third = np.float32(1 / 3)
        assert np.array_equal(net.output("A.OUTPUT"), [third] * 3 + [0] * 7)
        assert np.array_equal(net.output("B.OUTPUT"), [0] * 7 + [third] * 3)
        assert np.array_equal(net.output("C.OUTPUT"), [0] * 3 + [third] * 3 + [0] * 4)
    finally:
        net.close()


def test_equal_min_and_max_codes_min_with_a_warning(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="K" data="7"/>\n'
                         '<module class="IntervalCoder" name="C" outputsize="5" min="1" '
                         'max="1"/>\n'
                         '<connection source="K.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert np.allclose(net.output("C.OUTPUT"), [1 / 3] * 3 + [0, 0])
        warnings = [m for (_, level, where, m) in net.log if where == "C" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()


def test_too_few_units_is_a_build_error(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="K" data="0"/>\n'
                       '<module class="IntervalCoder" name="C" outputsize="3"/>\n'
                       '<connection source="K.OUTPUT" target="C.INPUT"/>')
