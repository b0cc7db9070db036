"""Tests of the PopulationDecoder module."""
import numpy as np

from ikaros.testing import load_body as load


def decode(x, sigma, lo, hi):
    """The decoded values, Ikaros 2's amplitudes (sums of absolute values) and the fitted
    Gaussian heights of the rows of x."""
    rows, n = x.shape
    values = lo + (hi - lo) * np.arange(n) / (n - 1)
    out, amp, fit = np.zeros(rows), np.zeros(rows), np.zeros(rows)
    for j in range(rows):
        w = x[j].sum()
        out[j] = (x[j] @ values) / w if w != 0 else (lo + hi) / 2
        amp[j] = np.abs(x[j]).sum()
        c = (n - 1) * (out[j] - lo) / (hi - lo)
        g = np.exp(-(np.arange(n) - c) ** 2 / (2 * sigma ** 2))
        fit[j] = (x[j] @ g) / (g @ g)
    return out, amp, fit


def test_decodes_random_rows_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="6" '
                         'outputsize_y="3" min="-0.2" seed="2"/>\n'
                         '<module class="PopulationDecoder" name="D" sigma="1.2" min="-1" '
                         'max="4"/>\n'
                         '<module class="PopulationDecoder" name="F" sigma="1.2" min="-1" '
                         'max="4" amplitude="fit"/>\n'
                         '<connection source="R.OUTPUT" target="D.INPUT" delay="0"/>\n'
                         '<connection source="R.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        assert net.output("D.OUTPUT").shape == (3,)
        assert net.output("D.AMPLITUDE").shape == (3,)
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            out, amp, fit = decode(x, 1.2, -1, 4)
            assert np.allclose(net.output("D.OUTPUT"), out, atol=1e-5)
            assert np.allclose(net.output("D.AMPLITUDE"), amp, atol=1e-5)
            assert np.allclose(net.output("F.OUTPUT"), out, atol=1e-5)
            assert np.allclose(net.output("F.AMPLITUDE"), fit, atol=1e-5)
    finally:
        net.close()


def test_round_trip_with_the_coder(tmp_path):
    # values away from the ends (where the code is cut off) come back with their amplitude:
    # Ikaros 2's rows of sum 1 times the amplitude, or (the options) Gaussians of height 1
    # times the amplitude, decoded with the fitted height
    body = ('<module class="Constant" name="X" data="0.4 0.5 0.55"/>\n'
            '<module class="Constant" name="A" data="1 0.5 3"/>\n'
            '<module class="PopulationCoder" name="C2" size="21" sigma="2"/>\n'
            '<module class="PopulationDecoder" name="D2"/>\n'
            '<connection source="X.OUTPUT" target="C2.INPUT" delay="0"/>\n'
            '<connection source="A.OUTPUT" target="C2.AMPLITUDE" delay="0"/>\n'
            '<connection source="C2.OUTPUT" target="D2.INPUT" delay="0"/>\n'
            '<module class="PopulationCoder" name="C" size="21" sigma="1.5" normalize="no" '
            'whole_sigma="no"/>\n'
            '<module class="PopulationDecoder" name="D" sigma="1.5" amplitude="fit"/>\n'
            '<connection source="X.OUTPUT" target="C.INPUT" delay="0"/>\n'
            '<connection source="A.OUTPUT" target="C.AMPLITUDE" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="D.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        for d in ("D", "D2"):
            assert np.allclose(net.output(f"{d}.OUTPUT"), [0.4, 0.5, 0.55], atol=1e-4)
            assert np.allclose(net.output(f"{d}.AMPLITUDE"), [1, 0.5, 3], atol=1e-4)
    finally:
        net.close()


def test_hand_worked_zero_row_1d_input_and_sigma_0(tmp_path):
    body = ('<module class="Constant" name="M" data="0 0 0; 1 0 1; 0 0 2"/>\n'
            '<module class="Constant" name="V" data="0 1 3"/>\n'
            '<module class="PopulationDecoder" name="D" sigma="0" min="2" max="4" '
            'amplitude="fit"/>\n'
            '<module class="PopulationDecoder" name="E" min="0" max="1"/>\n'
            '<connection source="M.OUTPUT" target="D.INPUT" delay="0"/>\n'
            '<connection source="V.OUTPUT" target="E.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        # unit values 2, 3, 4: an empty row -> the middle 3; [1 0 1] -> 3; [0 0 2] -> 4
        assert np.array_equal(net.output("D.OUTPUT"), [3, 3, 4])
        assert np.array_equal(net.output("D.AMPLITUDE"), [0, 0, 2])   # the nearest unit
        assert net.output("E.OUTPUT").shape == (1,)
        assert np.isclose(net.output("E.OUTPUT")[0], (0.5 + 3) / 4)
        assert net.output("E.AMPLITUDE")[0] == 4                      # 0 + 1 + 3
    finally:
        net.close()
