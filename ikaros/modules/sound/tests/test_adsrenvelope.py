"""ADSREnvelope's segments, computed here from the linear ADSR: attack 1/(attack·sr) per
sample up to 1, decay (1 − sustain)/(decay·sr) per sample down to sustain, release from the
level at the gate's fall to 0 in release seconds."""
import numpy as np

from ikaros.testing import load_body as load

SR = 1000           # with a tick of 10 ms: 10 samples a tick


def envelope(tmp_path, attrs, gate=None, trig=None):
    body = f'<module class="ADSREnvelope" name="E" {attrs}/>'
    for name, values in (("GATE", gate), ("TRIG", trig)):
        if values is not None:
            rows = "\n".join(" ".join(str(v) for v in row) for row in values)
            (tmp_path / f"{name}.txt").write_text(f"V/{len(values[0])}\n{rows}\n")
            body += (f'<module class="InputFile" name="{name}" filename="{name}.txt"/>'
                     f'<connection source="{name}.V" target="E.{name}" delay="0"/>')
    return load(tmp_path, body, sample_rate=str(SR), tick_duration="0.01")


def run(net, ticks):
    out = []
    for _ in range(ticks):
        net.step()
        out.extend(net.output("E.OUTPUT").tolist())
    return np.array(out)


def test_gate_held_then_released(tmp_path):
    # attack 4 samples (0.25 a sample), decay 3 samples (0.2 a sample) to 0.4, release
    # 5 samples from 0.4 (0.08 a sample)
    net = envelope(tmp_path, 'attack="0.004" decay="0.003" sustain="0.4" release="0.005"',
                   gate=[[1], [1], [0], [0]])
    try:
        got = run(net, 4)
    finally:
        net.close()
    attack = [0.25, 0.5, 0.75, 1.0]
    decay = [0.8, 0.6, 0.4]
    sustain = [0.4] * (20 - 7)
    release = [0.4 - 0.08 * k for k in range(1, 6)]
    expected = np.float32(attack + decay + sustain + release + [0.0] * 15)
    assert np.allclose(got, expected, atol=1e-6)
    assert got[-15:].tolist() == [0.0] * 15


def test_a_gate_per_sample_releases_during_the_attack(tmp_path):
    gate = [[1, 1, 0, 0, 0, 0, 0, 0, 0, 0]]
    net = envelope(tmp_path, 'attack="0.004" decay="0.01" sustain="0.5" release="0.004"',
                   gate=gate)
    try:
        got = run(net, 1)
    finally:
        net.close()
    # two attack steps to 0.5, then the release from 0.5 in 4 samples: 0.125 a sample
    assert np.allclose(got, [0.25, 0.5, 0.375, 0.25, 0.125, 0, 0, 0, 0, 0], atol=1e-6)


def test_trig_alone_is_attack_decay_release(tmp_path):
    net = envelope(tmp_path, 'attack="0" decay="0.002" sustain="0.6" release="0.003"',
                   trig=[[1], [1], [1]])
    try:
        got = run(net, 3)
    finally:
        net.close()
    # attack of 0 s: 1 in the first sample; decay 0.2 a sample; the release starts when
    # the decay ends, from 0.6 in 3 samples; the held TRIG does not start it again
    expected = [1.0, 0.8, 0.6, 0.4, 0.2, 0.0] + [0.0] * 24
    assert np.allclose(got, expected, atol=1e-6)


def test_trig_restarts_the_attack_from_the_present_level(tmp_path):
    trig = [[0, 0, 0, 0, 0, 1, 0, 0, 0, 0]]
    net = envelope(tmp_path, 'attack="0.004" decay="0.004" sustain="0.5" release="0.1"',
                   gate=[[1]], trig=trig)
    try:
        got = run(net, 1)
    finally:
        net.close()
    # the gate rises on sample 0: 0.25, 0.5, 0.75, 1, decay 0.125 a sample; TRIG rises on
    # sample 5 (level 0.875): the attack goes on from there
    assert np.allclose(got, [0.25, 0.5, 0.75, 1.0, 0.875, 1.0, 0.875, 0.75, 0.625, 0.5],
                       atol=1e-6)


def test_without_inputs_the_envelope_is_silent(tmp_path):
    net = envelope(tmp_path, "")
    try:
        assert run(net, 2).tolist() == [0.0] * 20
    finally:
        net.close()
