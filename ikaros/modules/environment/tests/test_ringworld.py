"""Tests of the RingWorld module (Ikaros 3, MODULES-V3 §16)."""
import numpy as np

from ikaros.testing import load_body as load

# angle, reward, punishment, intensity, two components
STIMULI = "3 1 0 0.5 1 2; -170 0 1 1 4 0; 30 0 0 2 0.5 0.25; 200 0 2 1 1 1"


def test_fovea_retina_and_auditory_map(tmp_path):
    net = load(tmp_path, f'<module class="Constant" name="S" data="{STIMULI}"/>'
                         '<module class="Constant" name="G" data="-2"/>'
                         '<module class="Constant" name="A" data="58 0.7; 100 1"/>'
                         '<module class="RingWorld" name="W" retina_width="5"/>'
                         '<connection source="S.OUTPUT" target="W.STIMULI" delay="0"/>'
                         '<connection source="G.OUTPUT" target="W.GAZE" delay="0"/>'
                         '<connection source="A.OUTPUT" target="W.AUDITORY_STIMULI" '
                         'delay="0"/>')
    try:
        net.step()
        # gaze -2: the stimulus at 3 is 5 degrees away (margin 4): none is fixated
        assert net.output("W.FOVEA").tolist() == [0, 0] and net.output("W.REWARD")[0] == 0
        retina = np.zeros((2, 5))
        # δ = 5 -> column round(65/120*4) = round(2.17) = 2; δ = 32 -> round(3.07) = 3
        retina[:, 2] = [0.5, 1.0]
        retina[:, 3] = [1.0, 0.5]
        assert np.allclose(net.output("W.RETINA"), retina)
        # 58 + 2 = 60 = half the view: column 4; 102 is out of view
        assert np.allclose(net.output("W.AUDITORY_MAP"), [[0, 0, 0, 0, 0.7]])
        assert not net.output("W.DISTAL_RETINA").any()
    finally:
        net.close()


def test_the_closest_stimulus_within_the_margin_is_fixated(tmp_path):
    net = load(tmp_path, f'<module class="Constant" name="S" data="{STIMULI}"/>'
                         '<module class="Constant" name="G" data="-168"/>'
                         '<module class="RingWorld" name="W" fixation_margin="10"/>'
                         '<connection source="S.OUTPUT" target="W.STIMULI" delay="0"/>'
                         '<connection source="G.OUTPUT" target="W.GAZE" delay="0"/>')
    try:
        net.step()
        # -170 is 2 degrees away, 200 (= -160) is 8: the first wins
        assert net.output("W.FOVEA").tolist() == [4, 0]
        assert net.output("W.PUNISHMENT")[0] == 1
    finally:
        net.close()
