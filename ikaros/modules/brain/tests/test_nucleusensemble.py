"""Tests of NucleusEnsemble against its equations in NumPy."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load


def f(x):
    return np.arctan(np.maximum(x, 0)) / math.tan(1)      # Ikaros 2's scaledsigmoid


def build(params, **inputs):
    text = f'<module class="NucleusEnsemble" name="N" {params}/>'
    for port, data in inputs.items():
        text += (f'<module class="Constant" name="C_{port}" data="{data}"/>'
                 f'<connection source="C_{port}.OUTPUT" target="N.{port}" delay="0"/>')
    return text


def run(tmp_path, ticks, params, **inputs):
    net = load(tmp_path, build(params, **inputs))
    try:
        rows = []
        for _ in range(ticks):
            net.step()
            rows.append({k: net.output(f"N.{k}").copy()
                         for k in ("OUTPUT", "THRESHOLD", "TETANUS", "ADENO_OUTPUT")})
        return rows
    finally:
        net.close()


def test_one_to_one_with_inhibition_and_shunting(tmp_path):
    e, i, s = np.array([1, 2, 3.]), np.array([0.5, 0, 4.]), np.array([1, 0, 0.])
    rows = run(tmp_path, 20, 'size="3" epsilon="0.2"', EXCITATION="1 2 3",
               INHIBITION="0.5 0 4", SHUNTING_INHIBITION="1 0 0")
    x = np.zeros(3)
    a = e / (1 + s) - i              # one input per nucleus: scale divides by 1
    for r in rows:
        x += 0.2 * (a - x)
        out = np.where(a >= 0, f(x), 0.0)        # threshold 0, tetanus = a
        assert np.allclose(r["OUTPUT"], out, atol=1e-6)
        assert np.allclose(r["TETANUS"], a) and np.array_equal(r["ADENO_OUTPUT"], r["OUTPUT"])


def test_all_to_all_wta_and_lateral(tmp_path):
    e = np.array([1, 2, 3, 4.])
    rows = run(tmp_path, 15, 'size="4" excitation_topology="all_to_all" '
               'inhibition_topology="wta" scale="no" activation_function="relu" epsilon="1"',
               EXCITATION="1 2 3 4", INHIBITION="1 0 0 2")
    a = e.sum() - (np.array([1, 0, 0, 2.]).sum() - np.array([1, 0, 0, 2.]))
    assert np.allclose(rows[-1]["OUTPUT"], np.maximum(a, 0))        # 10 - others' inhibition
    rows = run(tmp_path, 5, 'size="4" inhibition_topology="lateral" scale="yes" '
               'activation_function="relu" epsilon="1"', EXCITATION="1 1 1 1",
               INHIBITION="0 0.4 0 0")
    # nucleus 0 and 2 neighbour element 1: mean of their two inhibitors = 0.2
    assert np.allclose(rows[-1]["OUTPUT"], [0.8, 1, 0.8, 1])


def test_thresholds_dopamine_adenosine_and_tetanus(tmp_path):
    rows = run(tmp_path, 6, 'size="2" threshold="1" rho="2" sigma="0.5" tetanus_leak="0.5" '
               'tetanus_factor="1" activation_function="secondorder" epsilon="1" alpha="0.1"',
               EXCITATION="0.4 0.4", DOPAMINE="0 2", ADENO_INPUT="0.25")
    # thresholds: max(0, 1 + 2 * 0.25 - 0.5 * dopamine) = 1.5 and 0.5
    assert np.allclose(rows[0]["THRESHOLD"], [1.5, 0.5])
    tet = np.zeros(2)
    for r in rows:
        tet = 0.5 * tet + 0.4
        assert np.allclose(r["TETANUS"], tet)
        active = tet >= np.array([1.5, 0.5])
        expected = np.where(active, 0.1 + 2 * 0.16 / 1.16, 0.1)
        assert np.allclose(r["OUTPUT"], expected, atol=1e-6)
    # the tetanus approaches 0.8: nucleus 1 becomes active on tick 1, nucleus 0 never
    assert rows[0]["OUTPUT"][1] == pytest.approx(0.1) and rows[1]["OUTPUT"][1] > 0.1
    assert rows[-1]["OUTPUT"][0] == pytest.approx(0.1)


def test_noradrenaline_and_recurrence(tmp_path):
    rows = run(tmp_path, 30, 'size="2" epsilon="0.5" recurrent_topology="excitatory" '
               'tau="0.5" activation_function="relu"', EXCITATION="1 1",
               NORADRENALINE="0.6 0.3")
    x, out = np.zeros(2), np.zeros(2)
    for r in rows:
        a = 1 + np.array([0.6, -0.3]) + 0.5 * out
        x += 0.5 * (a - x)
        out = np.maximum(x, 0)
        assert np.allclose(r["OUTPUT"], out, atol=1e-5)


def test_setpoint_adapts_the_gain(tmp_path):
    rows = run(tmp_path, 3000, 'size="2" epsilon="1" activation_function="relu" '
               'moving_avg_window_size="20"', EXCITATION="1 1", SETPOINT="0.5 2",
               ADAPTATIONRATE="0.01")
    assert np.allclose(rows[-1]["OUTPUT"], [0.5, 2], atol=0.05)


def test_nothing_connected(tmp_path):
    rows = run(tmp_path, 3, 'size="3" alpha="0.3"')
    assert np.allclose(rows[-1]["OUTPUT"], 0.3)       # drive 0 reaches threshold 0
