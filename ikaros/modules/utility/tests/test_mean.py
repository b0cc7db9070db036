"""Tests of the Mean module."""

import numpy as np

from ikaros.testing import load_body as load


def test_hand_worked_matrix(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; 3 6"/>'
                         '<module class="Mean" name="M"/>'
                         '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.step()
        out = net.output("M.OUTPUT")
        assert out.shape == (1,) and out.dtype == np.float32
        assert out[0] == 3.0
    finally:
        net.close()


def test_follows_a_changing_input(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="5" outputsize_y="3" '
                         'min="-2" max="3" seed="7"/>'
                         '<module class="Mean" name="M"/>'
                         '<connection source="R.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        for _ in range(5):
            net.step()
            r = net.output("R.OUTPUT").astype(np.float64)
            assert np.isclose(net.output("M.OUTPUT")[0], r.sum() / r.size, rtol=1e-6)
    finally:
        net.close()


def test_single_element(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="-4.5"/>'
                         '<module class="Mean" name="M"/>'
                         '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.step()
        assert net.output("M.OUTPUT")[0] == -4.5
    finally:
        net.close()
