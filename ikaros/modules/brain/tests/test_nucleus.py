"""Tests of Nucleus (and the shared scalar nucleus equation)."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load


def reference(ticks, e, i, s, alpha=0.0, beta=1.0, phi=1.0, chi=1.0, psi=1.0, scale=True,
              epsilon=0.1):
    pool = (lambda v: float(np.mean(v))) if scale else (lambda v: float(np.sum(v)))
    E, I, S = (pool(v) if v is not None else 0.0 for v in (e, i, s))
    x, out = 0.0, []
    for _ in range(ticks):
        a = phi * E / (1 + max(psi * S, 0.0)) - chi * I
        x += epsilon * (a - x)
        out.append(alpha + beta * (math.atan(x) / math.atan(1) if x > 0 else 0.0))
    return out


def body(cls, params, e=None, i=None, s=None):
    text = f'<module class="{cls}" name="N" {params}/>'
    for name, port, data in (("E", "EXCITATION", e), ("I", "INHIBITION", i),
                             ("S", "SHUNTING_INHIBITION", s)):
        if data is not None:
            text += (f'<module class="Constant" name="{name}" data="{" ".join(map(str, data))}"/>'
                     f'<connection source="{name}.OUTPUT" target="N.{port}" delay="0"/>')
    return text


CASES = [
    ("", [1.0, 3.0], [0.5], [1.0, 1.0, 4.0], {}),
    ('scale="no" epsilon="0.3" alpha="0.2" beta="2"', [1.0, 3.0], [0.5], [1.0],
     dict(scale=False, epsilon=0.3, alpha=0.2, beta=2.0)),
    ('phi="2" chi="0.5" psi="0.25"', [2.0], [1.0, 3.0], None, dict(phi=2.0, chi=0.5, psi=0.25)),
    ('chi="3"', [1.0], [1.0], None, dict(chi=3.0)),            # x < 0: output alpha (0)
    ("", None, None, None, {}),                                 # nothing connected
    ('psi="-1"', [1.0], None, [2.0], dict(psi=-1.0)),          # negative shunting counts as 0
]


@pytest.mark.parametrize("cls", ["Nucleus", "NeuralField"])
@pytest.mark.parametrize("params,e,i,s,kw", CASES)
def test_matches_the_equation(tmp_path, cls, params, e, i, s, kw):
    net = load(tmp_path, body(cls, params, e, i, s))
    try:
        expected = reference(30, e, i, s, **kw)
        for t in range(30):
            net.step()
            got = net.output("N.OUTPUT")
            assert got.shape == (1,)
            assert got[0] == pytest.approx(expected[t], abs=1e-6), t
    finally:
        net.close()


def test_hand_worked_values(tmp_path):
    # E = mean(1, 3) = 2, no inhibition: x = 0.2 after one tick and x -> 2 in the limit
    net = load(tmp_path, body("Nucleus", "", [1, 3]))
    try:
        net.step()
        assert net.output("N.OUTPUT")[0] == pytest.approx(math.atan(0.2) / math.atan(1))
        net.run(ticks=300)
        assert net.output("N.OUTPUT")[0] == pytest.approx(math.atan(2) / math.atan(1), 1e-5)
    finally:
        net.close()
