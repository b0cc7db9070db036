"""Tests of the WilsonCowan module (Ikaros 3, MODULES-V3 §10)."""
import math

import pytest

from ikaros.testing import load_body as load


def sigmoid(d):
    return 100 / (1 + math.exp(-0.15 * (d - 10)))


def reference(model, p, q, ticks, r=0.002):
    """The equations of MODULES-V3 §10 with the default weights: the outputs of each tick
    (the inner rates and targets of the tick before)."""
    e = i = 0.0
    last, out = (0.0, 0.0, 0.0, 0.0), []
    for _ in range(ticks):
        t_e = (1 + model * (min(max(1 - r * e, 0), 1) - 1)) * sigmoid(0.8 * e + p - 0.6 * i)
        t_i = (1 + model * (min(max(1 - r * i, 0), 1) - 1)) * sigmoid(0.7 * e + q - 0.4 * i)
        out.append(last)
        e, i = min(max(t_e, 0), 100), min(max(t_i, 0), 100)
        last = (e, i, t_e, t_i)
    return out


@pytest.mark.parametrize("model", [0, 1, 0.5])
def test_outputs_are_the_previous_ticks_rates_and_targets(tmp_path, model):
    net = load(tmp_path, '<module class="Constant" name="P" data="6"/>'
                         '<module class="Constant" name="Q" data="2"/>'
                         f'<module class="WilsonCowan" name="W" model="{model}"/>'
                         '<connection source="P.OUTPUT" target="W.EXTERNAL_EXCITATION" '
                         'delay="0"/>'
                         '<connection source="Q.OUTPUT" target="W.EXTERNAL_INHIBITION" '
                         'delay="0"/>')
    try:
        for expected in reference(model, 6, 2, 6):
            net.step()
            got = [float(net.output(f"W.{k}")[0]) for k in
                   ("EXCITATORY_RATE", "INHIBITORY_RATE", "EXCITATORY_TARGET",
                    "INHIBITORY_TARGET")]
            assert got == pytest.approx(expected, rel=1e-6)
    finally:
        net.close()


def test_the_reference_table_model_0(tmp_path):
    # MODULES-V3 §10 [oracle], model 0, P = 6 and Q = 2 arriving on the second tick:
    # EXCITATORY_RATE is 0, 18.242552, 48.682217 on ticks 1, 2, 3
    (tmp_path / "pq.txt").write_text("P/1 Q/1\n0 0\n6 2\n6 2\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="pq.txt"/>'
                         '<module class="WilsonCowan" name="W" model="0"/>'
                         '<connection source="F.P" target="W.EXTERNAL_EXCITATION" delay="0"/>'
                         '<connection source="F.Q" target="W.EXTERNAL_INHIBITION" delay="0"/>')
    try:
        got = []
        for _ in range(3):
            net.step()
            got.append(float(net.output("W.EXCITATORY_RATE")[0]))
        assert got == pytest.approx([0, 18.242552, 48.682217], abs=1e-4)
    finally:
        net.close()
