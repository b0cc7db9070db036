"""AudioOscillator against Ikaros 3's reference (MODULES-V3 §21: the oracle of a saw at
100 Hz sampled at 400 Hz, and the per-sample phase formula computed here with plain NumPy)."""
import math

import numpy as np
import pytest

import ikaros
from ikaros.errors import ModelError
from ikaros.testing import load_body as load


def oscillator(tmp_path, attrs="", body="", **top):
    top = {"sample_rate": "400", "tick_duration": "0.01", **top}
    return load(tmp_path, f'<module class="AudioOscillator" name="O" {attrs}/>{body}', **top)


def reference(frequencies, sample_rate, shape, volume=1.0, duty=0.5, phase=0.0):
    """Samples by the reference's loop: the sample from the phase, then p += f/sr,
    p -= floor(p)."""
    out = []
    for f in frequencies:
        if shape == "sine":
            w = math.sin(2 * math.pi * phase)
        elif shape == "square":
            w = 1.0 if math.sin(2 * math.pi * phase) > 0 else -1.0
        elif shape == "saw":
            w = 2 * phase - 1
        elif shape == "triangle":
            w = 4 * abs(phase - 0.5) - 1
        elif shape == "ramp":
            w = 1 - 2 * phase
        else:
            w = 1.0 if phase < duty else -1.0
        out.append(volume * w)
        phase += max(0.0, f) / sample_rate
        phase -= math.floor(phase)
    return np.float32(out), phase


def test_the_reference_saw_at_100_hz_sampled_at_400(tmp_path):
    net = oscillator(tmp_path, 'wave_shape="saw" frequency="100"')
    try:
        assert net.output("O.OUTPUT").shape == (4,)
        for _ in range(3):
            net.step()
            assert net.output("O.OUTPUT").tolist() == [-1, -0.5, 0, 0.5]
    finally:
        net.close()


@pytest.mark.parametrize("shape", ["sine", "square", "saw", "triangle", "ramp", "pulse"])
def test_every_shape_carries_its_phase_over_ticks(tmp_path, shape):
    net = oscillator(tmp_path, f'wave_shape="{shape}" frequency="33" detune="4" '
                               f'multiplier="1.5" volume="0.8" duty_cycle="0.3"',
                     sample_rate="1000", tick_duration="0.02")
    try:
        got = []
        for _ in range(4):
            net.step()
            got.append(net.output("O.OUTPUT").copy())
        expected, _ = reference([33 * 1.5 + 4] * 80, 1000, shape, 0.8, 0.3)
        assert np.array_equal(np.concatenate(got), expected)
    finally:
        net.close()


def test_input_per_sample_and_modulation_for_the_block(tmp_path):
    body = ('<module class="Constant" name="F" data="100 200 300 400 500"/>'
            '<module class="Constant" name="M" data="-100 7"/>'
            '<connection source="F.OUTPUT" target="O.INPUT" delay="0"/>'
            '<connection source="M.OUTPUT" target="O.MODULATION" delay="0"/>')
    net = oscillator(tmp_path, 'wave_shape="sine" modulation_gain="2"', body,
                     sample_rate="5000", tick_duration="0.001")
    try:
        # INPUT has one value per sample; MODULATION is shorter, so its first element
        # (times 2) goes to every sample: 100 - 200 is below 0 and clipped to 0 Hz
        frequencies = [f - 200 for f in (100, 200, 300, 400, 500)]
        phase = 0.0
        for _ in range(2):
            net.step()
            expected, phase = reference(frequencies, 5000, "sine", phase=phase)
            assert np.array_equal(net.output("O.OUTPUT"), expected)
        assert phase != 0
    finally:
        net.close()


def test_a_one_value_input_sets_every_sample(tmp_path):
    body = ('<module class="Constant" name="F" data="250"/>'
            '<connection source="F.OUTPUT" target="O.INPUT" delay="0"/>')
    net = oscillator(tmp_path, 'wave_shape="triangle"', body, sample_rate="1000",
                     tick_duration="0.008")
    try:
        net.step()
        expected, _ = reference([250.0] * 8, 1000, "triangle")
        assert np.array_equal(net.output("O.OUTPUT"), expected)
        assert expected.tolist() == [1, 0, -1, 0, 1, 0, -1, 0]
    finally:
        net.close()


def test_a_wave_shape_by_its_index(tmp_path):
    net = oscillator(tmp_path, 'wave_shape="4" frequency="100"')     # ramp
    try:
        net.step()
        assert net.output("O.OUTPUT").tolist() == [1, 0.5, 0, -0.5]
    finally:
        net.close()


def test_sample_rate_0_does_not_build(tmp_path):
    with pytest.raises(ModelError, match="sample_rate is 0: set it") as e:
        oscillator(tmp_path, "", sample_rate="0")
    assert "model.ikg:2" in str(e.value)


def test_a_block_that_is_not_whole_is_cut_down_with_a_warning(tmp_path):
    net = oscillator(tmp_path, "", sample_rate="450")                 # 4.5 samples a tick
    try:
        assert net.output("O.OUTPUT").shape == (4,)
        assert any("is not a whole number of samples: a block has 4" in entry[3]
                   for entry in net.log)
    finally:
        net.close()


def test_the_block_follows_the_tick_duration_of_the_command_line(tmp_path):
    (tmp_path / "m.ikg").write_text('<group sample_rate="1000"><module class="AudioOscillator"'
                                    ' name="O"/></group>')
    with ikaros.load(str(tmp_path / "m.ikg"), tick_duration="0.05") as net:
        assert net.output("O.OUTPUT").shape == (50,)
    with ikaros.load(str(tmp_path / "m.ikg"), dialect="2") as net:    # Ikaros 2: 10 ms
        assert net.output("O.OUTPUT").shape == (10,)
    with ikaros.load(str(tmp_path / "m.ikg")) as net:                 # Ikaros 3: 1 s
        assert net.dialect == "3"
        assert net.output("O.OUTPUT").shape == (1000,)


def test_the_block_is_sized_by_the_languages_tick_duration_not_a_parameter(tmp_path):
    # Ikaros 3's interface has no tick_duration parameter: @tick_duration is the variable,
    # which a group inside the model may set (with a warning: the model ticks otherwise)
    assert "tick_duration" not in [p.name for p in
                                   ikaros.classes()["AudioOscillator"].parameters]
    (tmp_path / "m.ikg").write_text(
        '<group sample_rate="1000" tick_duration="0.01">\n'
        '  <group name="G" tick_duration="0.02">\n'
        '    <module class="AudioOscillator" name="O"/>\n  </group>\n</group>\n')
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        assert net.output("G.O.OUTPUT").shape == (20,)
        [warning] = net.warnings
        assert (warning.line, warning.message) == (
            3, "the block has 20 samples (a tick_duration set inside the model sizes it), "
               "but the model ticks every 0.01 s: sample_rate × 0.01 s = 10 samples")
