"""Tests of NeuralArray against its equation in NumPy."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def reference(ticks, e, i, s, alpha=0.001, beta=1.0, phi=1.0, chi=1.0, psi=1.0, scale=True,
              epsilon=0.1):
    i = np.asarray(i, float)
    a = np.zeros_like(i)
    sh = 0.0 if s is None else (np.mean(s) if scale else np.sum(s))
    out = []
    for _ in range(ticks):
        drive = -chi * i
        if e is not None:
            drive = drive + phi * np.asarray(e, float) / (1 + max(psi * sh, 0.0))
        a = a + epsilon * (drive - a) + alpha * (1 - a)
        out.append((a.copy(), beta * np.maximum(a, 0)))
    return out


def build(params, e, i, s):
    text = (f'<module class="NeuralArray" name="N" {params}/>'
            f'<module class="Constant" name="I" data="{" ".join(map(str, i))}"/>'
            '<connection source="I.OUTPUT" target="N.INHIBITION" delay="0"/>')
    if e is not None:
        text += (f'<module class="Constant" name="E" data="{" ".join(map(str, e))}"/>'
                 '<connection source="E.OUTPUT" target="N.EXCITATION" delay="0"/>')
    if s is not None:
        text += (f'<module class="Constant" name="S" data="{" ".join(map(str, s))}"/>'
                 '<connection source="S.OUTPUT" target="N.SHUNTING_INHIBITION" delay="0"/>')
    return text


@pytest.mark.parametrize("params,e,i,s,kw", [
    ("", [1, 0.5, 0, 2], [0, 0, 1, 0.5], [1, 3], {}),
    ('alpha="0" beta="2" phi="0.5" chi="2" psi="0.5" scale="no" epsilon="0.3"',
     [1, 2, 3], [0.2, 0, 1], [1, 1],
     dict(alpha=0.0, beta=2.0, phi=0.5, chi=2.0, psi=0.5, scale=False, epsilon=0.3)),
    ('alpha="0.05"', None, [0, 0.5], None, dict(alpha=0.05)),      # no excitation
])
def test_matches_the_equation(tmp_path, params, e, i, s, kw):
    net = load(tmp_path, build(params, e, i, s))
    try:
        expected = reference(40, e, i, s, **kw)
        for t in range(40):
            net.step()
            act, out = expected[t]
            assert np.allclose(net.output("N.ACTIVITY"), act, atol=1e-6)
            assert np.allclose(net.output("N.OUTPUT"), out, atol=1e-6)
    finally:
        net.close()


def test_noise_is_seeded(tmp_path):
    def run(seed):
        net = load(tmp_path, build(f'noise="0.1" seed="{seed}"', None, [0, 0, 0], None))
        try:
            net.run(ticks=10)
            return net.output("N.ACTIVITY").copy()
        finally:
            net.close()
    a, b, c = run(3), run(3), run(4)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    assert np.std(a) > 0.01


def test_excitation_size_must_match(tmp_path):
    with pytest.raises(Exception, match="same size"):
        net = load(tmp_path, build("", [1, 2], [0, 0, 0], None))
        try:
            net.run(ticks=1)
        finally:
            net.close()
