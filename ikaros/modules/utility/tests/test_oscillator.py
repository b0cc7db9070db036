"""Tests of the Oscillator module (Ikaros 3, MODULES-V3 §1)."""
import numpy as np

from ikaros.testing import load_body as load


def _run(tmp_path, attrs, ticks=6, tick_duration="0.1"):
    net = load(tmp_path, f'<module class="Oscillator" name="O" {attrs}/>',
               tick_duration=tick_duration)
    out = []
    try:
        for _ in range(ticks):
            net.step()
            out.append((float(np.float32(net.clock.time)), net.output("O.OUTPUT").copy()))
    finally:
        net.close()
    return out


def test_sine_per_frequency_keeps_the_matrix_shape(tmp_path):
    f = np.array([[1, 0.5], [2, 3]])
    for t, out in _run(tmp_path, 'frequency="1, 0.5; 2, 3"'):
        assert out.shape == (2, 2)
        assert np.allclose(out, np.sin(2 * np.pi * t * f), atol=1e-6)


def test_the_reference_values_at_a_tenth_of_a_second(tmp_path):
    # MODULES-V3 §1 [oracle]: t = 0.1 s gives (0.5878, 0.3090; 0.9511, 0.9511)
    for t, out in _run(tmp_path, 'frequency="1, 0.5; 2, 3"', ticks=3):
        if abs(t - 0.1) < 1e-6:
            assert np.allclose(out, [[0.5878, 0.3090], [0.9511, 0.9511]], atol=1e-4)
            return
    raise AssertionError("no tick at t = 0.1 s")


def test_square_is_one_where_the_sine_is_positive_else_zero(tmp_path):
    f = np.float32([0.15, 0.3, 0]).astype(float)     # a matrix holds float32
    for t, out in _run(tmp_path, 'type="square" frequency="0.15, 0.3, 0"', ticks=8,
                       tick_duration="1"):
        assert np.array_equal(out, (np.sin(2 * np.pi * t * f) > 0).astype(np.float32))
