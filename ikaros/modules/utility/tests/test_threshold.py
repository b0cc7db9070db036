"""Tests of the Threshold module."""
import numpy as np

from ikaros.testing import load_body as load

RANDOM = ('<module class="Randomizer" name="R" outputsize_x="5" outputsize_y="2" min="-1" '
          'max="1" seed="11"/>\n<connection source="R.OUTPUT" target="T.INPUT" delay="0"/>\n')


def test_binary_by_default(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="Threshold" name="T" threshold="0.2"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT")
            assert np.array_equal(net.output("T.OUTPUT"), (x > np.float32(0.2)).astype(float))
    finally:
        net.close()


def test_linear(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="Threshold" name="T" threshold="-0.25" '
                                  'type="linear"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT")
            expected = np.where(x > np.float32(-0.25), x - np.float32(-0.25), 0)
            assert np.allclose(net.output("T.OUTPUT"), expected, atol=1e-7)
    finally:
        net.close()


def test_hand_worked_edge_at_the_threshold_and_bypass(tmp_path):
    body = ('<module class="Constant" name="C" data="0.5 0.4 0.6 -3"/>\n'
            '<module class="Threshold" name="B" threshold="0.5"/>\n'
            '<module class="Threshold" name="L" threshold="0.5" type="linear"/>\n'
            '<module class="Threshold" name="P" threshold="0.5" bypass="yes"/>\n'
            '<connection source="C.OUTPUT" target="B.INPUT" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="P.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        assert np.array_equal(net.output("B.OUTPUT"), [0, 0, 1, 0])
        assert np.allclose(net.output("L.OUTPUT"), [0, 0, 0.1, 0])
        assert np.array_equal(net.output("P.OUTPUT"), np.float32([0.5, 0.4, 0.6, -3]))
        net.set_parameter("P.bypass", False)
        net.step()
        assert np.array_equal(net.output("P.OUTPUT"), [0, 0, 1, 0])
    finally:
        net.close()
