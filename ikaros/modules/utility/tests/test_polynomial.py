"""Tests of the Polynomial module: sum of c[k] x^(k + 1) over every coefficient given, whatever
order says (golden-v2 Polynomial)."""

import numpy as np

from ikaros.module import WARNING
from ikaros.testing import load_body as load


def run(tmp_path, data, attrs, ticks=1):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="Polynomial" name="P" {attrs}/>'
                         '<connection source="C.OUTPUT" target="P.INPUT" delay="0"/>')
    try:
        net.run(ticks=ticks)
        return net.output("P.OUTPUT"), [e for e in net.log if e[1] == WARNING]
    finally:
        net.close()


def test_defaults_copy_the_input(tmp_path):
    out, warnings = run(tmp_path, "1 -2; 3.5 0", "")
    assert out.shape == (2, 2) and out.dtype == np.float32
    assert np.array_equal(out, [[1, -2], [3.5, 0]])
    assert not warnings


def test_hand_worked_cubic(tmp_path):
    # 2x - x^2 + 0.5x^3 at x = -1, 0, 2: -3.5, 0, 4
    out, _ = run(tmp_path, "-1 0 2", 'order="3" coefficients="2 -1 0.5"', ticks=2)
    assert np.allclose(out, [-3.5, 0, 4])


def test_every_coefficient_counts_whatever_the_order_with_one_warning(tmp_path):
    out, warnings = run(tmp_path, "2 3", 'order="1" coefficients="3 100 -1"', ticks=3)
    assert np.allclose(out, [3 * 2 + 100 * 4 - 8, 3 * 3 + 100 * 9 - 27])
    assert len(warnings) == 1
    out, warnings = run(tmp_path, "2 3", 'order="3" coefficients="1"')
    assert np.allclose(out, [2, 3])
    assert len(warnings) == 1


def test_golden_cubic_with_four_coefficients(tmp_path):
    # golden-v2 Polynomial "cubic": order 3, four coefficients, all used
    x = np.array([0.5, -1, 2, 0.25])
    out, _ = run(tmp_path, "0.5 -1 2 0.25", 'order="3" coefficients="1 -0.5 0.25 2"')
    assert np.allclose(out, x - 0.5 * x ** 2 + 0.25 * x ** 3 + 2 * x ** 4)


def test_random_input_matches_numpy(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="5" min="-2" max="2" '
                         'seed="4"/>'
                         '<module class="Polynomial" name="P" order="4" '
                         'coefficients="0.5 -1 0.25 0.1"/>'
                         '<connection source="R.OUTPUT" target="P.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            expected = 0.5 * x - x ** 2 + 0.25 * x ** 3 + 0.1 * x ** 4
            assert np.allclose(net.output("P.OUTPUT"), expected, atol=1e-5)
    finally:
        net.close()
