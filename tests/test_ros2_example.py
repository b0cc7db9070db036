"""examples/ros2: the Braitenberg model drives the stand-in robot over ROS 2 topics (DDS on
this machine only)."""
import os
import subprocess
import sys
import time

from ikaros.hardware.ros2 import LOOPBACK

os.environ["CYCLONEDDS_URI"] = LOOPBACK         # before this process's first participant

import ikaros  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLE = os.path.join(ROOT, "examples", "ros2")


def test_the_vehicle_drives_the_stand_in_robot(monkeypatch):
    domain = str(100 + (os.getpid() + 7) % 100)
    monkeypatch.setenv("ROS_DOMAIN_ID", domain)
    robot = subprocess.Popen([sys.executable, os.path.join(EXAMPLE, "standin_robot.py"),
                              "--loopback", "--seconds", "60"], stdout=subprocess.PIPE,
                             text=True, env=dict(os.environ, PYTHONPATH=ROOT))
    try:
        assert robot.stdout.readline().startswith("stand-in robot:")
        with ikaros.load(os.path.join(EXAMPLE, "braitenberg.ikg")) as net:
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline and not (
                    net.output("Pose.RECEIVED")[0] > 0 and net.output("Pose.OUTPUT")[0] > 0.2):
                net.run(ticks=10, real_time=True)
            x, y, heading = net.output("Pose.OUTPUT")
            left, right = net.output("Ranges.OUTPUT")
            net.run(ticks=1)         # the vehicle reads the ranges a tick later (delay 1)
            twist = net.output("Vehicle.OUTPUT")
            assert net.output("Ranges.STALE")[0] == 0.0
    finally:
        robot.kill()
        robot.wait(10)
    assert x > 0.2                         # it moved forward, as the twist told it
    assert abs(twist[0] - 0.25 * (left + right)) < 1e-5
    assert abs(twist[5] - 1.5 * (left - right)) < 1e-5
