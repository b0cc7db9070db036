"""Tests of the FunctionGenerator module."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load


def run(tmp_path, attrs, ticks=12):
    net = load(tmp_path, f'<module class="FunctionGenerator" name="G" {attrs}/>')
    try:
        assert np.all(net.output("G.OUTPUT") == 0)          # init
        got = []
        for _ in range(ticks):
            net.step()
            out = net.output("G.OUTPUT")
            assert np.all(out == out[0])
            got.append(float(out[0]))
        return np.array(got), net.output("G.OUTPUT").shape
    finally:
        net.close()


def test_every_element_gets_the_value_as_in_ikaros_2(tmp_path):
    # golden-v2 FunctionGenerator: size="4" gives four equal elements at every tick
    net = load(tmp_path, '<module class="FunctionGenerator" name="G" size="3" offset="2"/>')
    try:
        net.step()
        assert net.output("G.OUTPUT").tolist() == [2, 2, 2]
    finally:
        net.close()


def test_sin_default_frequency(tmp_path):
    got, shape = run(tmp_path, 'size="3" offset="0.5" amplitude="2"')
    t = np.arange(12)
    assert shape == (3,)
    assert np.allclose(got, 0.5 + 2 * np.sin(0.15707963267949 * t), atol=1e-6)


def test_sin_with_shift(tmp_path):
    got, _ = run(tmp_path, 'type="sin" frequency="0.5" shift="2"')
    assert np.allclose(got, np.sin(0.5 * (np.arange(12) + 2)), atol=1e-6)


def test_triangle_ramp_square_hand_worked(tmp_path):
    f = math.pi / 2          # a period of 4 ticks: phases 0, 1/4, 1/2, 3/4
    tri, _ = run(tmp_path, f'type="triangle" frequency="{f!r}"', ticks=8)
    assert np.allclose(tri, [0, 0.5, 1, 0.5] * 2, atol=1e-6)
    ramp, _ = run(tmp_path, f'type="ramp" frequency="{f!r}"', ticks=8)
    assert np.allclose(ramp, [0, 0.25, 0.5, 0.75] * 2, atol=1e-6)
    sq, _ = run(tmp_path, f'type="square" frequency="{f!r}" duty="0.2"', ticks=8)
    assert np.array_equal(sq, [1, 0, 0, 0] * 2)
    sq, _ = run(tmp_path, f'type="square" frequency="{f!r}" duty="0.6" offset="-1" '
                'amplitude="2"', ticks=8)
    assert np.array_equal(sq, [1, 1, 1, -1] * 2)


def test_negative_shift_mirrors_the_wave_as_in_the_original(tmp_path):
    f = math.pi / 2
    ramp, _ = run(tmp_path, f'type="ramp" frequency="{f!r}" shift="-3"', ticks=4)
    assert np.allclose(ramp, [-0.75, -0.5, -0.25, 0], atol=1e-6)   # trunc of (t - 3)/4


def test_fraction_floor_continues_the_wave(tmp_path):
    f = math.pi / 2
    ramp, _ = run(tmp_path, f'type="ramp" frequency="{f!r}" shift="-3" fraction="floor"',
                  ticks=4)
    assert np.allclose(ramp, [0.25, 0.5, 0.75, 0], atol=1e-6)      # phase of t - 3


def test_ticksquare(tmp_path):
    got, _ = run(tmp_path, 'type="ticksquare" basetime="3" tickduty="1"', ticks=7)
    assert np.array_equal(got, [1, 0, 0, 1, 0, 0, 1])
    got, _ = run(tmp_path, 'type="ticksquare" basetime="4" tickduty="3" amplitude="2"',
                 ticks=5)
    assert np.array_equal(got, [2, 2, 2, 0, 2])


def test_ticksquare_zero_basetime_is_zero_with_a_warning(tmp_path):
    net = load(tmp_path, '<module class="FunctionGenerator" name="G" type="ticksquare" '
               'basetime="0" offset="0.25"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("G.OUTPUT"), [0.25])
        assert sum("basetime" in entry[3] for entry in net.log) == 1
    finally:
        net.close()


@pytest.mark.parametrize("kind", ["sin", "triangle", "ramp", "square"])
def test_type_by_index_from_a_model(tmp_path, kind):
    index = ["sin", "triangle", "ramp", "square"].index(kind)
    a, _ = run(tmp_path, f'type="{index}" frequency="0.7"', ticks=5)
    b, _ = run(tmp_path, f'type="{kind}" frequency="0.7"', ticks=5)
    assert np.array_equal(a, b)


def _v3(tmp_path, attrs, ticks, tick_duration):
    net = load(tmp_path, f'<module class="FunctionGenerator" name="F" {attrs}/>',
               dialect="3", tick_duration=tick_duration)
    out = []
    try:
        for _ in range(ticks):
            net.step()
            out.append((net.clock.time, float(net.output("F.OUTPUT")[0])))
    finally:
        net.close()
    return out


def test_ikaros_3_sine_is_of_the_time_in_seconds(tmp_path):
    # MODULES-V3 §23: p = frequency * (t + shift) with t in seconds; [oracle] tick_duration
    # 0.25, frequency 1: 0.2474 at t = 0.25 s, 0.8415 at t = 1 s
    for t, v in _v3(tmp_path, 'type="sine" frequency="1"', 5, "0.25"):
        assert v == pytest.approx(math.sin(t), abs=1e-6)
        if t in (0.25, 1.0):
            assert v == pytest.approx({0.25: 0.2474, 1.0: 0.8415}[t], abs=1e-4)


def test_ikaros_3_ticksquare_counts_whole_seconds(tmp_path):
    # [oracle] tick_duration 0.25, basetime 3, tickduty 1: 1 while int(t) is 0, then 0
    for t, v in _v3(tmp_path, 'type="ticksquare" basetime="3" tickduty="1"', 8, "0.25"):
        assert v == (1.0 if int(t) % 3 < 1 else 0.0)


def test_ikaros_3_phase_truncates_so_negative_time_mirrors(tmp_path):
    # Ikaros 3 takes the fraction with trunc: ramp at p = -pi is -0.5, not 0.5
    for t, v in _v3(tmp_path, 'type="ramp" frequency="1" shift="-3.14159265"', 1, "1"):
        p = (t - 3.14159265) / (2 * math.pi)
        assert v == pytest.approx(p - math.trunc(p), abs=1e-6)


def test_ikaros_3_defaults(tmp_path):
    net = load(tmp_path, '<module class="FunctionGenerator" name="F"/>', dialect="3")
    try:
        assert net.parameter("F.frequency") == 440
        assert net.parameter("F.basetime") == 100 and net.parameter("F.tickduty") == 50
    finally:
        net.close()
