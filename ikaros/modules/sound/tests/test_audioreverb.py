"""AudioReverb against scipy.signal.lfilter of its parts: the pre-delay, eight low-pass
feedback combs with Freeverb's delays (comb delay M, feedback g, damping d:
z^-M (1 - d z^-1) / (1 - d z^-1 - g (1-d) z^-M)), their mean, and four all-pass filters
(delay M: (z^-M - 0.5) / (1 - 0.5 z^-M))."""
import numpy as np
from scipy import signal

from ikaros.testing import load_body as load

FREEVERB_COMBS = [1116, 1188, 1277, 1356, 1422, 1491, 1557, 1617]
FREEVERB_ALLPASSES = [556, 441, 341, 225]


def reverb(tmp_path, attrs, ticks, sample_rate):
    body = ('<module class="AudioOscillator" name="S" wave_shape="pulse" frequency="3" '
            'duty_cycle="0.01"/>'
            f'<module class="AudioReverb" name="R" {attrs}/>'
            '<connection source="S.OUTPUT" target="R.INPUT" delay="0"/>')
    net = load(tmp_path, body, sample_rate=str(sample_rate), tick_duration="0.02")
    x, y = [], []
    try:
        for _ in range(ticks):
            net.step()
            x.append(net.output("S.OUTPUT").copy())
            y.append(net.output("R.OUTPUT").copy())
    finally:
        net.close()
    return np.concatenate(x).astype(np.float64), np.concatenate(y)


def expected_wet(x, sample_rate, decay, damping, pre_delay):
    p = round(pre_delay * sample_rate)
    x = np.concatenate([np.zeros(p), x])[:len(x)]
    combs = []
    for m in FREEVERB_COMBS:
        m = max(1, round(m * sample_rate / 44100))
        b = np.zeros(m + 1)
        b[m] = 1
        b2 = np.convolve(b, [1, -damping])
        a = np.zeros(m + 1)
        a[0], a[1] = 1, -damping
        a[m] += -decay * (1 - damping)
        combs.append(signal.lfilter(b2, a, x))
    wet = np.mean(combs, axis=0)
    for m in FREEVERB_ALLPASSES:
        m = max(1, round(m * sample_rate / 44100))
        b = np.zeros(m + 1)
        b[0], b[m] = -0.5, 1
        a = np.zeros(m + 1)
        a[0], a[m] = 1, -0.5
        wet = signal.lfilter(b, a, wet)
    return wet


def test_the_reverberation_is_combs_and_allpasses(tmp_path):
    x, y = reverb(tmp_path, 'mix="0.4" decay="0.8" damping="0.3" pre_delay="0.005"', 20,
                  11025)
    wet = expected_wet(x, 11025, 0.8, 0.3, 0.005)
    assert np.abs(wet).max() > 0.1
    assert np.allclose(y, 0.6 * x + 0.4 * wet, atol=1e-5)


def test_no_pre_delay_and_the_feedback_kept_below_one(tmp_path):
    x, y = reverb(tmp_path, 'mix="1" decay="1" damping="0" pre_delay="0"', 10, 4400)
    assert np.allclose(y, expected_wet(x, 4400, 0.99, 0.0, 0.0), atol=1e-5)
