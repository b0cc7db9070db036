"""Tests of NeuralField: the scalar nucleus equation of Ikaros 2's Nucleus."""
import math

import pytest

from ikaros.testing import load_body as load


def test_shunting_divides_the_excitation(tmp_path):
    # E = 3 (sum), S = 2 (sum), psi 0.5: drive 3 / 2 = 1.5; inhibition 1 * chi 0.5 -> 1.0
    net = load(tmp_path, '<module class="Constant" name="E" data="1 2"/>'
               '<module class="Constant" name="S" data="2"/>'
               '<module class="Constant" name="I" data="1"/>'
               '<module class="NeuralField" name="F" scale="no" psi="0.5" chi="0.5" '
               'epsilon="1"/>'
               '<connection source="E.OUTPUT" target="F.EXCITATION" delay="0"/>'
               '<connection source="S.OUTPUT" target="F.SHUNTING_INHIBITION" delay="0"/>'
               '<connection source="I.OUTPUT" target="F.INHIBITION" delay="0"/>')
    try:
        for _ in range(3):
            net.step()
            assert net.output("F.OUTPUT")[0] == pytest.approx(math.atan(1) / math.tan(1))
    finally:
        net.close()


def test_unconnected_gives_0_not_alpha(tmp_path):
    net = load(tmp_path, '<module class="NeuralField" name="F" alpha="0.25" beta="3"/>')
    try:
        assert net.output("F.OUTPUT")[0] == 0
        net.run(ticks=4)
        assert net.output("F.OUTPUT")[0] == 0          # x stays 0: not above 0
    finally:
        net.close()


def test_approaches_its_fixed_point(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="E" data="0.5"/>'
               '<module class="NeuralField" name="F" epsilon="0.5" beta="2" alpha="0.1"/>'
               '<connection source="E.OUTPUT" target="F.EXCITATION" delay="0"/>')
    try:
        xs = []
        for _ in range(20):
            net.step()
            xs.append(math.tan((net.output("F.OUTPUT")[0] - 0.1) / 2 * math.tan(1)))
        # x_t = 0.5 (1 - 0.5^t)
        assert xs[0] == pytest.approx(0.25, rel=1e-5) and xs[1] == pytest.approx(0.375, rel=1e-5)
        assert xs[-1] == pytest.approx(0.5, rel=1e-5)
    finally:
        net.close()
