"""AudioSynth: each voice's wave, computed here with the wave formulas of Ikaros 3's
AudioOscillator (MODULES-V3 §21), summed while its TRIGGER is above 0."""
import math

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load


def synth(tmp_path, rows, sample_rate=200):
    """A synth fed from an InputFile: per tick the wave shapes, frequencies, amplitudes and
    triggers of two voices."""
    text = "W/2 F/2 A/2 T/2\n" + "\n".join(" ".join(str(v) for v in row) for row in rows)
    (tmp_path / "in.txt").write_text(text + "\n")
    body = ('<module class="InputFile" name="I" filename="in.txt"/>'
            f'<module class="AudioSynth" name="Y" sample_rate="{sample_rate}"/>'
            '<connection source="I.W" target="Y.WAVESHAPE" delay="0"/>'
            '<connection source="I.F" target="Y.FREQUENCY" delay="0"/>'
            '<connection source="I.A" target="Y.AMPLITUDE" delay="0"/>'
            '<connection source="I.T" target="Y.TRIGGER" delay="0"/>')
    return load(tmp_path, body)


def voice(shape, frequency, amplitude, n, sample_rate, phase=0.0):
    out = []
    for _ in range(n):
        w = {0: math.sin(2 * math.pi * phase),
             1: 1.0 if math.sin(2 * math.pi * phase) > 0 else -1.0,
             2: 2 * phase - 1, 3: 4 * abs(phase - 0.5) - 1, 4: 1 - 2 * phase,
             5: 1.0 if phase < 0.5 else -1.0}[shape]
        out.append(amplitude * w)
        phase += frequency / sample_rate
        phase -= math.floor(phase)
    return np.array(out), phase


def test_two_voices_are_summed_while_triggered(tmp_path):
    rows = [[0, 2, 10, 25, 0.5, 0.25, 1, 1],
            [0, 2, 10, 25, 0.5, 0.25, 1, 0],       # voice 2 stops
            [0, 3, 10, 25, 0.5, 0.25, 1, 1]]       # voice 2 starts again, from phase 0
    net = synth(tmp_path, rows)
    try:
        assert net.output("Y.OUTPUT").shape == (20,)              # 200 samples/s × 0.1 s
        got = []
        for _ in range(3):
            net.step()
            got.append(net.output("Y.OUTPUT").copy())
    finally:
        net.close()
    v1, p1 = voice(0, 10, 0.5, 20, 200)
    v2, _ = voice(2, 25, 0.25, 20, 200)
    assert np.allclose(got[0], v1 + v2, atol=1e-6)
    v1, p1 = voice(0, 10, 0.5, 20, 200, p1)
    assert np.allclose(got[1], v1, atol=1e-6)
    v1, _ = voice(0, 10, 0.5, 20, 200, p1)
    v2, _ = voice(3, 25, 0.25, 20, 200)
    assert np.allclose(got[2], v1 + v2, atol=1e-6)


def test_shapes_are_rounded_and_kept_in_range(tmp_path):
    net = synth(tmp_path, [[7, -2, 20, 20, 1, 1, 1, 1]])
    try:
        net.step()
        pulse, _ = voice(5, 20, 1, 20, 200)
        sine, _ = voice(0, 20, 1, 20, 200)
        assert np.allclose(net.output("Y.OUTPUT"), pulse + sine, atol=1e-6)
    finally:
        net.close()


def test_the_synth_needs_a_sample_rate(tmp_path):
    (tmp_path / "in.txt").write_text("W/1 F/1 A/1 T/1\n0 1 1 1\n")
    with pytest.raises(ModelError, match="sample_rate is 0"):
        load(tmp_path, '<module class="InputFile" name="I" filename="in.txt"/>'
                       '<module class="AudioSynth" name="Y" sample_rate="0"/>'
                       '<connection source="I.W" target="Y.WAVESHAPE"/>'
                       '<connection source="I.F" target="Y.FREQUENCY"/>'
                       '<connection source="I.A" target="Y.AMPLITUDE"/>'
                       '<connection source="I.T" target="Y.TRIGGER"/>')
