"""Tests of Nucleus: the Ikaros 2 equation (shared with NeuralField), checked against the
golden files of Ikaros 2 (golden-v2 Nucleus), and this project's reading of the Ikaros 3
interface, against the equations written out here."""
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
        out.append(alpha + beta * math.atan(x) / math.tan(1) if x > 0 else 0.0)
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
    ('chi="3" alpha="0.5"', [1.0], [1.0], None, dict(chi=3.0, alpha=0.5)),   # x < 0: 0
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
        assert net.output("N.OUTPUT")[0] == pytest.approx(math.atan(0.2) / math.tan(1))
        assert net.output("N.X")[0] == pytest.approx(0.2)
        net.run(ticks=300)
        assert net.output("N.OUTPUT")[0] == pytest.approx(math.atan(2) / math.tan(1), 1e-5)
    finally:
        net.close()


def test_golden_excitation_case(tmp_path):
    """golden-v2 Nucleus "excitation": E = (0.5, 1, 2), every default."""
    net = load(tmp_path, body("Nucleus", "", [0.5, 1, 2]))
    try:
        net.step()
        assert net.output("N.OUTPUT")[0] == pytest.approx(0.0745736882, abs=1e-7)
        net.run(ticks=9)
        assert net.output("N.OUTPUT")[0] == pytest.approx(0.4172262251, abs=1e-7)
    finally:
        net.close()


# --- Ikaros 3 files ---------------------------------------------------------------------------

ACT = {"atan": lambda u: math.atan(u) / math.tan(1) if u > 0 else 0.0,
       "threshold": lambda u: 1.0 if u > 0 else 0.0, "ReLU": lambda u: max(u, 0.0),
       "tanh": math.tanh, "sigmoid": lambda u: 1 / (1 + math.exp(-u)), "linear": lambda u: u}


def reference3(ticks, e, i, s, alpha=0.0, beta=1.0, gamma=1.0, delta=1.0, psi=1.0,
               epsilon=1.0, time_constant=1.0, dt=1.0, theta=0.0, offset=0.0, gain=1.0,
               f="atan", scale=True):
    pool = (lambda v: float(np.mean(v))) if scale else (lambda v: float(np.sum(v)))
    E, I, S = (pool(v) if v is not None else 0.0 for v in (e, i, s))
    x, xs, out = 0.0, [], []
    for _ in range(ticks):
        a = alpha + beta * E / (1 + max(delta * psi * S, 0.0)) - gamma * I
        x += min(1.0, epsilon * dt / time_constant) * (a - x)
        xs.append(x)
        out.append(offset + gain * ACT[f](x - theta))
    return xs, out


CASES3 = [
    ("", [1.0, 3.0], [0.5], [1.0, 1.0, 4.0], {}),
    ('alpha="0.3" beta="2" gamma="0.5" delta="0.5" psi="2" scale_inputs="no"', [1.0, 3.0],
     [0.5, 0.5], [1.0], dict(alpha=0.3, beta=2, gamma=0.5, delta=0.5, psi=2, scale=False)),
    ('epsilon="0.5" time_constant="2" theta="0.2" output_offset="1" output_scale="3"',
     [2.0], [1.0], None, dict(epsilon=0.5, time_constant=2, theta=0.2, offset=1, gain=3)),
] + [(f'activation_function="{f}" theta="0.4"', [1.0], [0.5, 1.5], None,
      dict(f=f, theta=0.4)) for f in ACT] + [
    ('time_constant="0.5" epsilon="0.2" activation_function="linear"', [1.0], None, None,
     dict(time_constant=0.5, epsilon=0.2, f="linear", dt=0.1)),
]


@pytest.mark.parametrize("params,e,i,s,kw", CASES3)
def test_ikaros3_matches_the_equation(tmp_path, params, e, i, s, kw):
    dt = kw.get("dt", 1.0)
    net = load(tmp_path, body("Nucleus", params, e, i, s), dialect="3", tick_duration=dt)
    try:
        xs, expected = reference3(12, e, i, s, **kw)
        for t in range(12):
            net.step()
            assert net.output("N.OUTPUT")[0] == pytest.approx(expected[t], abs=1e-6), t
            assert net.output("N.X")[0] == pytest.approx(xs[t], abs=1e-6), t
    finally:
        net.close()


def test_ikaros3_noise_has_sigma_and_the_seed_repeats_it(tmp_path):
    runs = []
    for seed in (5, 5, 6):
        net = load(tmp_path, body("Nucleus", f'sigma="0.5" seed="{seed}" '
                                             'activation_function="linear"', [1.0]),
                   dialect="3")
        xs = []
        for _ in range(2000):
            net.step()
            xs.append(float(net.output("N.X")[0]))
        net.close()
        runs.append(np.array(xs))
    assert np.array_equal(runs[0], runs[1]) and not np.array_equal(runs[0], runs[2])
    # X = 1 + 0.5 N(0, 1) each tick (epsilon 1): mean 1, standard deviation 0.5
    assert abs(runs[0].mean() - 1) < 0.05 and abs(runs[0].std() - 0.5) < 0.03


def test_ikaros3_bursts(tmp_path):
    """Drive 1 above theta 0.5 (X = 1 at once): after burst_time 2 s above it, a burst of
    3 s at level 5; then X = reset_level -1 and 2 s with no burst, while X climbs back."""
    params = ('burst_duration="3" burst_time="2" refractory_period="2" reset_level="-1" '
              'burst_level="5" theta="0.5" epsilon="0.5" activation_function="linear"')
    net = load(tmp_path, body("Nucleus", params, [1.0]), dialect="3")
    try:
        out, xs = [], []
        for _ in range(14):
            net.step()
            out.append(round(float(net.output("N.OUTPUT")[0]), 6))
            xs.append(round(float(net.output("N.X")[0]), 6))
    finally:
        net.close()
    # X: 0.5, 0.75, 0.875 (above 0.5 from tick 2), ...; the state follows 0.5 (1 - X) each
    # tick; linear output X - 0.5 outside bursts
    expected_x, expected_out, x = [], [], 0.0
    phases = ["free", "free", "free", "burst", "burst", "burst", "end", "free", "free",
              "free", "free", "burst", "burst", "burst"]
    for phase in phases:
        x += 0.5 * (1 - x)
        if phase == "end":
            x = -1.0
        expected_x.append(round(x, 6))
        expected_out.append(5.0 if phase == "burst" else round(x - 0.5, 6))
    assert xs == pytest.approx(expected_x, abs=1e-6)
    assert out == pytest.approx(expected_out, abs=1e-6)
