"""AudioFilter against scipy.signal.lfilter with the low-pass coefficients of R. Bristow-
Johnson's Audio EQ Cookbook (computed here), and against the filter's response at its
cutoff."""
import math

import numpy as np
import pytest
from scipy import signal

from ikaros.testing import load_body as load

SR = 8000


def cookbook_lowpass(f0, q, sr):
    w0 = 2 * math.pi * f0 / sr
    alpha = math.sin(w0) / (2 * q)
    b = [(1 - math.cos(w0)) / 2, 1 - math.cos(w0), (1 - math.cos(w0)) / 2]
    a = [1 + alpha, -2 * math.cos(w0), 1 - alpha]
    return b, a


def filtered(tmp_path, filter_attrs, osc_attrs, ticks, extra=""):
    body = (f'<module class="AudioOscillator" name="O" {osc_attrs}/>'
            f'<module class="AudioFilter" name="F" {filter_attrs}/>'
            f'<connection source="O.OUTPUT" target="F.INPUT" delay="0"/>{extra}')
    net = load(tmp_path, body, sample_rate=str(SR), tick_duration="0.01")
    x, y = [], []
    try:
        for _ in range(ticks):
            net.step()
            x.append(net.output("O.OUTPUT").copy())
            y.append(net.output("F.OUTPUT").copy())
    finally:
        net.close()
    return np.concatenate(x).astype(np.float64), np.concatenate(y)


@pytest.mark.parametrize("resonance, q", [(0, 1 / math.sqrt(2)), (0.5, 5.353553390593274),
                                          (1, 10.0)])
def test_a_fixed_cutoff_is_the_cookbook_low_pass(tmp_path, resonance, q):
    x, y = filtered(tmp_path, f'cutoff="700" resonance="{resonance}"',
                    'wave_shape="saw" frequency="310"', 6)
    assert abs(q - (1 / math.sqrt(2) + resonance * (10 - 1 / math.sqrt(2)))) < 1e-12
    b, a = cookbook_lowpass(700, q, SR)
    assert np.allclose(y, signal.lfilter(b, a, x), atol=1e-5)      # memory across ticks


def test_the_envelope_moves_the_cutoff_by_octaves(tmp_path):
    extra = ('<module class="Constant" name="M" data="1.5"/>'
             '<connection source="M.OUTPUT" target="F.CUTOFF_MOD" delay="0"/>')
    x, y = filtered(tmp_path, 'cutoff="200" envelope_amount="2"',
                    'wave_shape="square" frequency="150"', 3, extra)
    b, a = cookbook_lowpass(200 * 2 ** 3, 1 / math.sqrt(2), SR)
    assert np.allclose(y, signal.lfilter(b, a, x), atol=1e-5)


def test_cutoff_and_resonance_per_sample_follow_the_difference_equation(tmp_path):
    (tmp_path / "c.txt").write_text("C/80 R/1\n" + " ".join(str(300 + 40 * i)
                                                           for i in range(80)) + " 0.25\n")
    extra = ('<module class="InputFile" name="C" filename="c.txt"/>'
             '<connection source="C.C" target="F.CUTOFF" delay="0"/>'
             '<connection source="C.R" target="F.RESONANCE_MOD" delay="0"/>')
    x, y = filtered(tmp_path, 'resonance="0.5"', 'wave_shape="saw" frequency="97"', 1, extra)
    x1 = x2 = y1 = y2 = 0.0
    expected = []
    for n, xn in enumerate(x):
        b, a = cookbook_lowpass(300 + 40 * n, 1 / math.sqrt(2) + 0.75 * (10 - 1 / math.sqrt(2)),
                                SR)
        yn = (b[0] * xn + b[1] * x1 + b[2] * x2 - a[1] * y1 - a[2] * y2) / a[0]
        x2, x1, y2, y1 = x1, xn, y1, yn
        expected.append(yn)
    assert np.allclose(y, expected, atol=1e-5)


def test_at_the_cutoff_a_butterworth_passes_one_over_root_two(tmp_path):
    x, y = filtered(tmp_path, 'cutoff="500"', 'wave_shape="sine" frequency="500"', 40)
    steady = y[-800:]
    assert abs(np.abs(steady).max() - 1 / math.sqrt(2)) < 2e-3
