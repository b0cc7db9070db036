"""The Epuck module against the virtual e-puck, and the obstacle-avoidance example."""
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import ikaros
from ikaros.errors import ModelError, RunError
from ikaros.hardware.epuck import METRES_PER_STEP
from ikaros.hardware.epuck_sim import Arena, VirtualEpuck
from ikaros.testing import load_body

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))
SIM = "sim:epuck?step=0.1&amp;obstacles=none"          # an empty 1 m x 1 m arena, start (0.2, 0.2)


def model(tmp_path, params, velocity="0.5 0.5", extra=""):
    body = (f'<module class="Constant" name="V" data="{velocity}"/>\n'
            f'<module class="Epuck" name="R" {params}/>\n'
            '<connection source="V.OUTPUT" target="R.VELOCITY" delay="0"/>\n' + extra)
    return load_body(tmp_path, body)


def simulator(net):
    return net.modules["R"].module._simulator


def test_a_velocity_that_has_no_value_from_its_source_yet_moves_nothing(tmp_path):
    """Constant -> Scale -> VELOCITY (delays 1) arrives on tick 2; the zeros before it are
    not sent (a D,0,0 would stop a robot someone else drives; a non-zero offset would move)."""
    extra = ('<module class="Constant" name="On" data="1"/>\n<module class="Scale" name="S" factor="1"/>\n'
             '<connection source="On.OUTPUT" target="S.INPUT"/>\n'
             '<connection source="S.OUTPUT" target="R.LIGHT"/>')
    net = load_body(tmp_path, f'<module class="Constant" name="V" data="0.5 0.5"/>\n'
                              f'<module class="Epuck" name="R" port="{SIM}" calibrate="no"/>\n'
                              '<module class="Scale" name="S2" factor="1"/>\n'
                              '<connection source="V.OUTPUT" target="S2.INPUT"/>\n'
                              '<connection source="S2.OUTPUT" target="R.VELOCITY"/>\n' + extra)
    robot = simulator(net)
    try:
        net.step()
        net.step()
        assert robot.commands == []
        net.step()
        assert robot.commands == ["D,500,500", "F,1"]
    finally:
        net.close()


def test_wheels_sensors_and_pose(tmp_path):
    net = model(tmp_path, f'port="{SIM}" proximity_on="yes" encoder_on="yes"')
    robot = simulator(net)
    try:
        assert robot.commands == ["K", "Q"]          # calibrate and read: nothing moves
        assert robot.speeds == [0, 0]
        for _ in range(10):
            net.step()
        assert robot.speeds == [500, 500]
        # each tick's wheel command first advances 0.1 s at the previous speeds
        assert net.output("R.ENCODER").tolist() == [450, 450]
        assert np.allclose(net.output("R.POSE"), [0.2 + 450 * METRES_PER_STEP, 0.2, 0],
                           atol=1e-6)
        assert net.output("R.PROXIMITY").tolist() == robot.proximity()
        assert robot.commands[2:5] == ["D,500,500", "N", "Q"]
    finally:
        net.close()
    assert robot.commands[-12:] == ["S"] + [f"L,{n},0" for n in range(8)] + \
        ["B,0", "F,0", "T,0"]
    assert robot.speeds == [0, 0] and robot.leds == [0] * 8


def test_leds_light_body_and_sound_are_sent_when_they_change(tmp_path):
    extra = ('<module class="Constant" name="L" data="1 0 1 0 0 0 0 1"/>\n'
             '<module class="Constant" name="On" data="1"/>\n'
             '<module class="Constant" name="S" data="2"/>\n'
             '<connection source="L.OUTPUT" target="R.LED"/>\n'
             '<connection source="On.OUTPUT" target="R.LIGHT"/>\n'
             '<connection source="On.OUTPUT" target="R.BODY"/>\n'
             '<connection source="S.OUTPUT" target="R.SOUND"/>\n')
    net = model(tmp_path, f'port="{SIM}"', "0 0", extra)
    robot = simulator(net)
    try:
        net.step()
        net.step()
        assert robot.leds == [1, 0, 1, 0, 0, 0, 0, 1]
        assert (robot.front_led, robot.body_led, robot.sound) == (1, 1, 2)
        assert robot.commands.count("L,0,1") == 1 and robot.commands.count("T,2") == 1
    finally:
        net.close()
    assert robot.leds == [0] * 8 and (robot.front_led, robot.body_led, robot.sound) == (0, 0, 0)


def test_accelerometer_microphones_and_camera(tmp_path):
    net = model(tmp_path, f'port="{SIM}" acceleration_on="yes" microphone_on="yes" '
                'camera="color" width="20" height="12"')
    try:
        net.step()
        assert net.output("R.ACCELERATION_PLAIN").tolist() == [2048, 2048, 2848]
        assert net.output("R.ACCELERATION").tolist() == [1.0]
        assert net.output("R.INCLINATION").tolist() == [0.0]
        assert net.output("R.MICROPHONE_VOLUME").tolist() == [20, 20, 20]
        assert net.output("R.RED").shape == (12, 20)
        expected = simulator(net).render()
        assert np.allclose(net.output("R.GREEN"), expected[..., 1], atol=1 / 63)
        assert np.allclose(net.output("R.IMAGE"), net.output("R.RED") / 3 +
                           net.output("R.GREEN") / 3 + net.output("R.BLUE") / 3, atol=1e-6)
    finally:
        net.close()


def test_an_image_of_another_format_than_asked_for_is_an_error_naming_the_port(tmp_path):
    net = model(tmp_path, f'port="{SIM}" camera="gray" width="20" height="12"')
    robot = simulator(net)
    try:
        net.step()
        robot.camera = (1, 40, 40, 8)                  # as the firmware does with an image too big
        with pytest.raises(RunError, match=f"the e-puck at '{robot.path}' sent a 40 x 40 colour image, "
                                           f"not the 20 x 12 grey one asked for"):
            net.step()
    finally:
        net.close()


def test_odometry_of_a_real_port_follows_the_robot(tmp_path):
    with VirtualEpuck(Arena(1, 1, []), x=0.5, y=0.5, step=0.1) as robot:
        net = model(tmp_path, f'port="{robot.path}" encoder_on="yes"', "0.3 0.5")
        try:
            for _ in range(30):
                net.step()
            start = np.array([0.5, 0.5, 0.0])
            assert np.allclose(net.output("R.POSE") + start, robot.pose, atol=2e-3)
            assert np.hypot(*(robot.pose[:2] - start[:2])) > 0.08       # it did move
        finally:
            net.close()


@pytest.mark.parametrize("fault, message", [("silent", "does not answer"),
                                            ("corrupt", "gave a corrupted reply")])
def test_a_faulty_robot_stops_the_run_naming_its_port(tmp_path, fault, message):
    net = model(tmp_path, f'port="{SIM}" proximity_on="yes"')
    robot = simulator(net)
    net.step()
    robot.fault = fault
    with pytest.raises(RunError, match=f"e-puck at '{robot.path}' {message}"):
        net.step()
    net.close()


def test_bad_settings_are_named(tmp_path):
    with pytest.raises(ModelError, match=r"a 80 x 60 gray image \(4800 bytes\) does not fit the e-puck's "
                                         r"camera buffer: 4056 bytes at most"):
        model(tmp_path, f'port="{SIM}" camera="gray" width="80" height="60"')
    with pytest.raises(ModelError, match="cannot open the e-puck at '/dev/no-epuck'"):
        model(tmp_path, 'port="/dev/no-epuck"')
    with pytest.raises(ModelError, match="inside a wall or an obstacle"):
        model(tmp_path, 'port="sim:epuck?x=0.01"')


def test_the_obstacle_example_avoids_every_obstacle():
    """examples/epuck_obstacles.ikg, headless for 1000 ticks (50 s simulated): the robot
    touches nothing and travels more than 3 m (at most 3.2 m is possible at its speed)."""
    net = ikaros.load(os.path.join(ROOT, "examples", "epuck_obstacles.ikg"))
    robot = net.modules["Robot"].module._simulator
    try:
        net.run(ticks=1000)
        assert robot.contacts == 0
        assert robot.distance > 3.0
        x, y, _ = robot.pose
        assert 0 < x < 1 and 0 < y < 1
    finally:
        net.close()


def test_the_watchdog_stops_an_idle_robot_and_ticks_resume(tmp_path):
    extra = ('<module class="Constant" name="L" data="1 1 1 1 1 1 1 1"/>\n'
             '<connection source="L.OUTPUT" target="R.LED" delay="0"/>\n')
    net = model(tmp_path, f'port="{SIM}" watchdog="0.2"', "0.5 0.5", extra)
    robot = simulator(net)
    try:
        net.step()
        assert robot.speeds == [500, 500] and robot.leds == [1] * 8
        deadline = time.monotonic() + 2.0
        while robot.commands[-1] != "T,0" and time.monotonic() < deadline:
            time.sleep(0.01)                          # the safe state's last command
        assert robot.speeds == [0, 0] and robot.leds == [0] * 8          # no tick for 0.2 s
        net.step()
        assert robot.speeds == [500, 500] and robot.leds == [1] * 8      # sent again
        net.command("R", "safe_state")
        assert robot.speeds == [0, 0] and robot.leds == [0] * 8
    finally:
        net.close()


@pytest.mark.parametrize("how", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_of_an_ikaros_process_stops_the_robot(tmp_path, how):
    with VirtualEpuck(Arena(1, 1, []), x=0.5, y=0.5) as robot:
        path = tmp_path / "drive.ikg"
        path.write_text('<group name="Drive" tick_duration="0.02">\n'
                        '<module class="Constant" name="V" data="0.3 0.3"/>\n'
                        '<module class="Constant" name="L" data="1 1 1 1 1 1 1 1"/>\n'
                        f'<module class="Epuck" name="R" port="{robot.path}"/>\n'
                        '<connection source="V.OUTPUT" target="R.VELOCITY"/>\n'
                        '<connection source="L.OUTPUT" target="R.LED"/>\n</group>\n')
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(
            p for p in [ROOT, os.environ.get("PYTHONPATH")] if p))
        process = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-r", str(path)],
                                   env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            deadline = time.monotonic() + 20
            while (robot.speeds, robot.leds) != ([300, 300], [1] * 8) and \
                    time.monotonic() < deadline:
                time.sleep(0.02)
            assert robot.speeds == [300, 300] and robot.leds == [1] * 8
            process.send_signal(how)
            process.wait(timeout=10)
        finally:
            if process.poll() is None:
                process.kill()
                process.wait(timeout=10)
        assert robot.speeds == [0, 0] and robot.leds == [0] * 8 and robot.commands[-1] == "T,0"


def test_an_exception_in_another_module_stops_the_robot(tmp_path):
    (tmp_path / "Boom.py").write_text(
        "from ikaros import Module\n\n\nclass Boom(Module):\n"
        "    def tick(self):\n"
        "        if self.clock.tick == 3:\n"
        "            raise RuntimeError('boom')\n")
    net = model(tmp_path, f'port="{SIM}"', "0.5 0.5", '<module class="Boom" name="B"/>\n')
    robot = simulator(net)
    with pytest.raises(RunError, match="RuntimeError: boom"):
        for _ in range(10):
            net.step()
    assert robot.speeds == [0, 0] and robot.commands[-1] == "T,0"
    assert net.tick == 4
    net.close()
