"""Tests of the PopulationCoder module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def code(x, size, sigma, lo, hi, amplitude=None, normalize=True):
    out = np.zeros((len(x), size))
    for j, v in enumerate(x):
        c = (size - 1) * (v - lo) / (hi - lo)
        for k in range(size):
            out[j, k] = np.exp(-(k - c) ** 2 / (2 * sigma ** 2))
        if normalize:
            out[j] /= out[j].sum()
    if amplitude is not None:
        out *= np.reshape(amplitude, (-1, 1)) if len(amplitude) > 1 else amplitude[0]
    return out


RANDOM = ('<module class="Randomizer" name="R" outputsize="3" min="-1" max="2" seed="4"/>\n'
          '<connection source="R.OUTPUT" target="P.INPUT" delay="0"/>\n')


def test_rows_of_gaussians_over_ticks(tmp_path):
    # Ikaros 2: sigma 2.7 is read as 2 and each row sums to 1; the options give a sigma of
    # 2.7 and curves of peak 1
    net = load(tmp_path, RANDOM + '<module class="PopulationCoder" name="P" size="7" '
                                  'sigma="2.7" min="-1" max="2"/>\n'
                                  '<module class="PopulationCoder" name="Q" size="7" '
                                  'sigma="2.7" min="-1" max="2" whole_sigma="no" '
                                  'normalize="no"/>\n'
                                  '<connection source="R.OUTPUT" target="Q.INPUT" delay="0"/>')
    try:
        assert net.output("P.OUTPUT").shape == (3, 7)
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            assert np.allclose(net.output("P.OUTPUT"), code(x, 7, 2, -1, 2), atol=1e-6)
            assert np.allclose(net.output("P.OUTPUT").sum(axis=1), 1, atol=1e-6)
            assert np.allclose(net.output("Q.OUTPUT"), code(x, 7, 2.7, -1, 2, normalize=False),
                               atol=1e-6)
    finally:
        net.close()


def test_amplitude_per_row_and_for_all(tmp_path):
    body = RANDOM + ('<module class="Randomizer" name="A" outputsize="3" seed="5"/>\n'
                     '<module class="Constant" name="K" data="2"/>\n'
                     '<module class="PopulationCoder" name="P" min="-1" max="2"/>\n'
                     '<module class="PopulationCoder" name="Q" min="-1" max="2"/>\n'
                     '<connection source="R.OUTPUT" target="Q.INPUT" delay="0"/>\n'
                     '<connection source="A.OUTPUT" target="P.AMPLITUDE" delay="0"/>\n'
                     '<connection source="K.OUTPUT" target="Q.AMPLITUDE" delay="0"/>')
    net = load(tmp_path, body)
    try:
        for _ in range(3):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            a = net.output("A.OUTPUT").astype(np.float64)
            assert np.allclose(net.output("P.OUTPUT"), code(x, 10, 1, -1, 2, a), atol=1e-6)
            assert np.allclose(net.output("Q.OUTPUT"), code(x, 10, 1, -1, 2, [2]), atol=1e-6)
    finally:
        net.close()


def test_hand_worked_sigma_below_1_and_equal_min_max(tmp_path):
    # sigma 0.5 is read as 0 (Ikaros 2): only a value exactly on a unit gives activity
    body = ('<module class="Constant" name="K" data="0.5 1 3"/>\n'
            '<module class="PopulationCoder" name="P" size="5" sigma="0.5"/>\n'
            '<module class="Constant" name="L" data="0.45"/>\n'
            '<module class="PopulationCoder" name="Z" size="6" sigma="0.5"/>\n'
            '<connection source="L.OUTPUT" target="Z.INPUT" delay="0"/>\n'
            '<module class="PopulationCoder" name="E" size="3" min="1" max="1"/>\n'
            '<connection source="K.OUTPUT" target="P.INPUT" delay="0"/>\n'
            '<connection source="K.OUTPUT" target="E.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.run(ticks=2)
        # positions 2, 4, 12 (outside: no unit)
        assert np.array_equal(net.output("P.OUTPUT"),
                              [[0, 0, 1, 0, 0], [0, 0, 0, 0, 1], [0, 0, 0, 0, 0]])
        assert np.array_equal(net.output("Z.OUTPUT"), [[0] * 6])     # 0.45 is at 2.25 units
        g = np.exp(-np.arange(3) ** 2 / 2)
        g /= g.sum()
        assert np.allclose(net.output("E.OUTPUT"), [g, g, g])
        warnings = [m for (_, level, where, m) in net.log if where == "E" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()


def test_amplitude_of_the_wrong_size_is_a_build_error(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="K" data="1 2 3"/>\n'
                       '<module class="Constant" name="A" data="1 2"/>\n'
                       '<module class="PopulationCoder" name="P"/>\n'
                       '<connection source="K.OUTPUT" target="P.INPUT"/>\n'
                       '<connection source="A.OUTPUT" target="P.AMPLITUDE"/>')
