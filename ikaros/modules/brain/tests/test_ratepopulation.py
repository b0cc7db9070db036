"""Tests of the RatePopulation module (Ikaros 3, MODULES-V3 §9)."""
import math

import numpy as np

from ikaros.testing import load_body as load

BODY = ('<module class="Constant" name="I" data="35.434 -4 200"/>'
        '<module class="RatePopulation" name="R" population_size="3" time_constant="0.01" '
        'initial_output="2" {attrs}/>'
        '<connection source="I.OUTPUT" target="R.INPUT" delay="0"/>')


def _run(tmp_path, attrs, ticks=3):
    net = load(tmp_path, BODY.format(attrs=attrs), tick_duration="0.001")
    try:
        out = []
        for _ in range(ticks):
            net.step()
            out.append((net.output("R.OUTPUT").copy(), net.output("R.ACTIVATION").copy()))
        return out
    finally:
        net.close()


def test_as_in_ikaros_3_the_output_is_the_target_and_activation_zero(tmp_path):
    # [oracle] linear, τ = 0.01, dt = 0.001, input 35.434: OUTPUT 35.434, ACTIVATION 0
    for out, act in _run(tmp_path, ""):
        assert np.allclose(out, [35.434, 0, 100]) and not act.any()


def test_filtered_follows_the_target_as_a_first_order_system(tmp_path):
    target = np.array([35.434, 0, 100])
    decay = math.exp(-0.001 / 0.01)
    y = np.full(3, 2.0)
    for out, act in _run(tmp_path, 'filtered="yes"'):
        y = target + (y - target) * decay
        assert np.allclose(out, y, rtol=1e-6) and np.allclose(act, target)


def test_sigmoid_relu_and_the_summed_drive(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="E" data="3 -2"/>'
                         '<module class="Constant" name="H" data="1 1"/>'
                         '<module class="RatePopulation" name="S" population_size="2" '
                         'activation_function="sigmoid" gain="0.5" sigmoid_midpoint="1" '
                         'bias="0.5" minimum_output="-1" maximum_output="3"/>'
                         '<module class="RatePopulation" name="U" population_size="2" '
                         'activation_function="relu" gain="2" bias="0.5"/>'
                         '<connection source="E.OUTPUT" target="S.EXCITATION" delay="0"/>'
                         '<connection source="H.OUTPUT" target="S.INHIBITION" delay="0"/>'
                         '<connection source="E.OUTPUT" target="U.EXCITATION" delay="0"/>'
                         '<connection source="H.OUTPUT" target="U.MODULATION" delay="0"/>')
    try:
        net.step()
        drive = np.array([3 - 1 + 0.5, -2 - 1 + 0.5])
        assert np.allclose(net.output("S.OUTPUT"),
                           -1 + 4 / (1 + np.exp(-0.5 * (drive - 1))), rtol=1e-6)
        assert np.allclose(net.output("U.OUTPUT"), [2 * 4.5, 0])
    finally:
        net.close()
