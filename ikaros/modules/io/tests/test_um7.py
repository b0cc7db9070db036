"""The UM7 module against the UM7 simulator on a pseudo-terminal (which speaks the UM7
Datasheet's binary packets; see ikaros/hardware/tests/test_um7_protocol.py). Expected
values: the Euler angles as the datasheet stores them, int16 counts of 1/91.02222 degree,
and the simulator's gravity at the given roll and pitch."""
import math

import numpy as np
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.hardware.um7_sim import VirtualUM7
from ikaros.testing import load_body as load, step_until


def counts(degrees):
    return round(degrees * 91.02222) / 91.02222


def test_euler_angles_gyro_and_accelerations_by_polling(tmp_path):
    net = load(tmp_path, '<module class="UM7" name="U" '
                         'port="sim:um7?roll=12.5&amp;pitch=-30&amp;yaw=170&amp;yaw_rate=0"/>')
    try:
        step_until(net, lambda: net.output("U.YAW")[0] != 0)
        net.step()
        expected = [counts(12.5), counts(-30), counts(170)]
        assert np.allclose(net.output("U.EulerAngles"), expected, atol=1e-5)
        assert np.allclose([net.output(f"U.{n}")[0] for n in ("ROLL", "PITCH", "YAW")],
                           expected, atol=1e-5)
        r, p = math.radians(12.5), math.radians(-30)
        g = 9.80665
        assert np.allclose(net.output("U.ProcessedAccel"),
                           [g * math.sin(p), -g * math.sin(r) * math.cos(p),
                            -g * math.cos(r) * math.cos(p)], atol=1e-5)
        assert net.output("U.ProcessedGyro").tolist() == [0, 0, 0]
    finally:
        net.close()


def test_without_polling_it_listens_to_broadcasts(tmp_path):
    net = load(tmp_path, '<module class="UM7" name="U" poll="no" '
                         'port="sim:um7?pitch=4&amp;yaw_rate=90&amp;rate=100"/>')
    try:
        step_until(net, lambda: net.output("U.ProcessedGyro")[2] != 0)
        assert net.output("U.ProcessedGyro").tolist() == [0, 0, 90]
        assert net.output("U.PITCH")[0] == pytest.approx(counts(4), abs=1e-5)
        first = net.output("U.YAW")[0]
        step_until(net, lambda: net.output("U.YAW")[0] > first + 1)     # it turns
    finally:
        net.close()


def test_a_missing_port_is_a_load_error(tmp_path):
    with pytest.raises(ModelError, match="cannot open the UM7 at '/dev/no-such-um7'"):
        load(tmp_path, '<module class="UM7" name="U" port="/dev/no-such-um7"/>')


def test_a_sensor_that_goes_away_stops_the_run(tmp_path):
    with VirtualUM7() as device:
        net = load(tmp_path, f'<module class="UM7" name="U" port="{device.path}"/>')
        try:
            net.step()
            device.disconnect()
            with pytest.raises(RunError, match="the UM7 at '/dev/pts/.*' cannot be "):
                step_until(net, lambda: False, seconds=3)
        finally:
            net.close()
