"""Tests of the BalkeniusReactiveControl module (Ikaros 3, MODULES-V3 §15)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

W = (0.5, 0.3, 0.2, 0.4, 0.1, 0.05)     # m, n, o, p, q, r


def expected(s_l, s_r, theta=0.05, threshold=0.0, gain=2.0, limit=0.25):
    m, n, o, p, q, r = W
    a_l, a_r, c = max(0, s_l - theta), max(0, s_r - theta), max(0, (s_l + s_r) / 2 - theta)
    left = max(0, r + m * s_r + o * s_l - n * a_l - q * a_r - p * c - threshold)
    right = max(0, r + m * s_l + o * s_r - n * a_r - q * a_l - p * c - threshold)
    return [left, right], list(np.clip(gain * np.array([left, right]), -limit, limit)), \
        [a_l, c, a_r]


@pytest.mark.parametrize("port, data", [("SENSORS", "0.3 0.1"),
                                        ("ODOUR", "9 0.3 7; 9 0.1 7; 5 5 5")])
def test_motor_from_sensors_or_an_odour_channel(tmp_path, port, data):
    weights = ", ".join(str(w) for w in W)
    net = load(tmp_path, f'<module class="Constant" name="S" data="{data}"/>'
                         f'<module class="BalkeniusReactiveControl" name="B" gain="2" '
                         f'weights="{weights}" odour_channel="1.2"/>'
                         f'<connection source="S.OUTPUT" target="B.{port}" delay="0"/>')
    try:
        net.step()
        raw, motor, nodes = expected(0.3, 0.1)
        assert np.allclose(net.output("B.RAW_MOTOR"), raw)
        assert np.allclose(net.output("B.MOTOR"), motor)
        assert np.allclose(net.output("B.NODES"), nodes)
        assert np.allclose(net.output("B.SENSORY"), [0.3, 0.1])
    finally:
        net.close()
