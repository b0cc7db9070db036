"""Tests of the Integrator module."""
import numpy as np

from ikaros.testing import load_body as load


def test_leaky_integration_matches_the_recurrence(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="3" '
               'outputsize_y="2" seed="7"/>'
               '<module class="Integrator" name="I" alpha="0.8" beta="0.5"/>'
               '<connection source="R.OUTPUT" target="I.INPUT" delay="0"/>')
    try:
        y = np.zeros((2, 3))
        assert np.array_equal(net.output("I.OUTPUT"), y)
        for _ in range(6):
            net.step()
            y = 0.8 * y + 0.5 * net.output("R.OUTPUT")
            assert np.allclose(net.output("I.OUTPUT"), y, atol=1e-6)
    finally:
        net.close()


def test_defaults_and_hand_worked(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="10"/>'
               '<module class="Integrator" name="I"/>'
               '<connection source="C.OUTPUT" target="I.INPUT" delay="0"/>')
    try:
        got = []
        for _ in range(3):
            net.step()
            got.append(float(net.output("I.OUTPUT")[0]))
        assert np.allclose(got, [1, 1.9, 2.71])
    finally:
        net.close()


def test_min_and_max_clip_and_empty_means_unlimited(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 -1"/>'
               '<module class="Integrator" name="A" alpha="1" beta="1" min="-2" max="3"/>'
               '<module class="Integrator" name="B" alpha="1" beta="1" max="0"/>'
               '<module class="Integrator" name="U" alpha="1" beta="1"/>'
               '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="B.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="U.INPUT" delay="0"/>')
    try:
        net.run(ticks=5)
        assert np.array_equal(net.output("A.OUTPUT"), [3, -2])
        assert np.array_equal(net.output("B.OUTPUT"), [0, -5])
        assert np.array_equal(net.output("U.OUTPUT"), [5, -5])
    finally:
        net.close()
