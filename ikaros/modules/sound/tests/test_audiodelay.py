"""AudioDelay's samples: an impulse's echoes, and any input against scipy.signal.lfilter
of the delay's transfer function, E/X = k z^-d / (1 - (1-k) z^-1 - g k z^-d), the echo e
of a line fed back through the one-pole low-pass filter k/(1 - (1-k) z^-1)."""
import math

import numpy as np
from scipy import signal

from ikaros.testing import load_body as load


def delayed(tmp_path, attrs, source, ticks, sample_rate=1000, tick="0.01", output="OUTPUT"):
    body = (f'{source}<module class="AudioDelay" name="D" {attrs}/>'
            f'<connection source="S.{output}" target="D.INPUT" delay="0"/>')
    net = load(tmp_path, body, sample_rate=str(sample_rate), tick_duration=tick)
    x, y = [], []
    try:
        for _ in range(ticks):
            net.step()
            x.append(net.output(f"S.{output}").copy())
            y.append(net.output("D.OUTPUT").copy())
    finally:
        net.close()
    return np.concatenate(x).astype(np.float64), np.concatenate(y)


def test_an_impulse_repeats_every_delay_time_with_the_feedback_gain(tmp_path):
    (tmp_path / "i.txt").write_text("V/10\n1 0 0 0 0 0 0 0 0 0\n" + "0 0 0 0 0 0 0 0 0 0\n" * 9)
    source = '<module class="InputFile" name="S" filename="i.txt"/>'
    x, y = delayed(tmp_path, 'delay_time="0.025" feedback_gain="0.5" mix="1" '
                             'lowpass_cutoff="0"', source, 10, output="V")
    expected = np.zeros(100)
    expected[[25, 50, 75]] = [1, 0.5, 0.25]
    assert y.tolist() == expected.tolist()


def test_mix_and_the_low_pass_filter_in_the_feedback(tmp_path):
    source = '<module class="AudioOscillator" name="S" wave_shape="saw" frequency="37"/>'
    x, y = delayed(tmp_path, 'delay_time="0.0075" feedback_gain="0.6" mix="0.3" '
                             'lowpass_cutoff="900"', source, 8, sample_rate=8000)
    d, g = 60, 0.6
    k = 1 - math.exp(-2 * math.pi * 900 / 8000)
    b = np.zeros(d + 1)
    b[d] = k
    a = np.zeros(d + 1)
    a[0], a[1], a[d] = 1, -(1 - k), -g * k
    echo = signal.lfilter(b, a, x)
    assert np.allclose(y, 0.7 * x + 0.3 * echo, atol=1e-5)


def test_a_delay_shorter_than_a_sample_is_one_sample(tmp_path):
    (tmp_path / "i.txt").write_text("V/4\n1 0 0 0\n")
    source = '<module class="InputFile" name="S" filename="i.txt"/>'
    x, y = delayed(tmp_path, 'delay_time="0" feedback_gain="0" mix="1" lowpass_cutoff="0"',
                   source, 1, sample_rate=400, output="V")
    assert y.tolist() == [0, 1, 0, 0]
