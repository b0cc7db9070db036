"""ROS2Publisher and ROS2Subscriber against a separate process with its own Cyclone DDS
participant, whose topic and type names are ROS 2's (defined here, as a ROS 2 node would
have them): it receives what the model publishes and publishes what the model reads."""
import os
import subprocess
import sys
import time

import numpy as np
import pytest

from ikaros.hardware.ros2 import LOOPBACK

os.environ["CYCLONEDDS_URI"] = LOOPBACK         # before this process's first participant

import ikaros  # noqa: E402

DOMAIN = str(100 + os.getpid() % 100)    # apart from other runs on this machine

# The other process: a "ROS 2 node" with its own participant and its own type definitions.
NODE = r'''
import sys, time
from dataclasses import dataclass
from cyclonedds.domain import DomainParticipant
from cyclonedds.topic import Topic
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.core import Qos, Policy
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import sequence, float64, int32, uint32

@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32

@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str

@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header
    name: sequence[str]
    position: sequence[float64]
    velocity: sequence[float64]
    effort: sequence[float64]

@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64
    y: float64
    z: float64

@dataclass
class Twist(IdlStruct, typename="geometry_msgs::msg::dds_::Twist_"):
    linear: Vector3
    angular: Vector3

qos = Qos(Policy.Reliability.Reliable(0), Policy.Durability.Volatile, Policy.History.KeepLast(10))
dp = DomainParticipant(int(sys.argv[1]))
joints = DataWriter(dp, Topic(dp, "rt/joint_states", JointState), qos=qos)
commands = DataReader(dp, Topic(dp, "rt/cmd_vel", Twist), qos=qos)
print("READY", flush=True)
end = time.time() + 60
while time.time() < end:
    joints.write(JointState(Header(Time(7, 5), "base"), ["wrist", "elbow", "shoulder"],
                            [3.0, 2.0, 1.0], [30.0, 20.0, 10.0], []))
    for twist in commands.take(10):
        print("TWIST", twist.linear.x, twist.linear.y, twist.angular.z, flush=True)
        raise SystemExit
    time.sleep(0.02)
'''

MODEL = """<group tick_duration="0.02">
  <module class="Constant" name="Command" data="0.5, 0, 0, 0, 0, -0.25"/>
  <module class="ROS2Publisher" name="CmdVel" topic="/cmd_vel" type="Twist"
          domain_id="{domain}"/>
  <module class="ROS2Subscriber" name="Joints" topic="/joint_states" type="JointState"
          names="shoulder, elbow" domain_id="{domain}"/>
  <connection source="Command.OUTPUT" target="CmdVel.INPUT" delay="0"/>
</group>"""


@pytest.fixture
def node():
    process = subprocess.Popen([sys.executable, "-c", NODE, DOMAIN], stdout=subprocess.PIPE,
                               text=True, env=dict(os.environ, CYCLONEDDS_URI=LOOPBACK))
    try:
        assert process.stdout.readline().strip() == "READY"
        yield process
    finally:
        process.kill()
        process.wait(10)


def test_a_ros_2_node_reads_what_the_model_publishes_and_the_model_reads_it(tmp_path, node):
    path = tmp_path / "m.ikg"
    path.write_text(MODEL.format(domain=DOMAIN))
    with ikaros.load(str(path)) as net:
        deadline = time.monotonic() + 30
        while net.output("Joints.RECEIVED")[0] == 0 and time.monotonic() < deadline:
            net.run(ticks=1, real_time=True)
        np.testing.assert_array_equal(net.output("Joints.OUTPUT"), [1.0, 2.0])
        np.testing.assert_array_equal(net.output("Joints.VELOCITY"), [10.0, 20.0])
        np.testing.assert_array_equal(net.output("Joints.EFFORT"), [0.0, 0.0])
        assert net.output("Joints.STALE")[0] == 0.0
        assert 0 <= net.output("Joints.AGE")[0] < 0.5
        while node.poll() is None and time.monotonic() < deadline:
            net.run(ticks=1, real_time=True)
    assert node.stdout.readline().split() == ["TWIST", "0.5", "0.0", "-0.25"]


def test_a_silent_topic_is_stale_and_holds_up_no_tick(tmp_path):
    path = tmp_path / "m.ikg"
    path.write_text(f"""<group tick_duration="0.01">
  <module class="ROS2Subscriber" name="S" topic="/nobody_publishes_this" size="4"
          stale_after="0.05" domain_id="{DOMAIN}"/>
</group>""")
    with ikaros.load(str(path)) as net:
        started = time.perf_counter()
        net.run(ticks=20, real_time=True)
        spent = time.perf_counter() - started
        figures = net.figures()
        assert net.output("S.STALE")[0] == 1.0
        assert net.output("S.RECEIVED")[0] == 0.0
        np.testing.assert_array_equal(net.output("S.OUTPUT"), np.zeros(4))
        assert net.output("S.AGE")[0] >= 0.19
    assert figures["resyncs"] == 0 and spent < 2.0


def test_without_the_extra_a_model_fails_at_load_with_the_pip_install(tmp_path, monkeypatch):
    for name in [n for n in sys.modules if n.split(".")[0] == "cyclonedds"] + ["cyclonedds"]:
        monkeypatch.setitem(sys.modules, name, None)
    monkeypatch.delitem(sys.modules, "ikaros.hardware.ros2.dds", raising=False)
    path = tmp_path / "m.ikg"
    path.write_text('<group><module class="ROS2Subscriber" name="S"/></group>')
    with pytest.raises(ikaros.ModelError, match=r"needs the package cyclonedds: "
                                                r"pip install 'ikaros\[ros2\]'"):
        ikaros.load(str(path))
