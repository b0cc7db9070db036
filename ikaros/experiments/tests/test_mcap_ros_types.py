"""MCAP recordings for ROS tools: images as sensor_msgs/Image, joint positions as
sensor_msgs/JointState, the QoS each topic was offered with, and metadata saying which
output is which topic and type; checked with the mcap reader, with rosbags (an independent
ROS 2 implementation) on the file, and on the rosbag2 folder rosbags converts it into.

Expected values follow the message definitions (sensor_msgs/Image: rgb8 is 3 bytes per
pixel, row-major, 32FC1 a little-endian float32 per pixel; sensor_msgs/JointState: position
in radians, REP 103) and rosbag2's offered_qos_profiles (QoS enums as rmw numbers)."""
import math
import os

import numpy as np
import pytest
from mcap.reader import make_reader
from rosbags.convert import convert
from rosbags.rosbag2 import Reader
from rosbags.rosbag2.metadata import parse_qos
from rosbags.typesys import Stores, get_typestore

import ikaros

MODEL = """<group tick_duration="0.5">
  <module class="Constant" name="Colour"
          data="[[[0, 0.5], [1, 0.25]], [[1, 1], [0, 0]], [[0.2, 0.4], [0.6, 0.8]]]"/>
  <module class="Constant" name="Gray" data="0.1 0.2 0.3; 0.4 0.5 0.6"/>
  <module class="Constant" name="Depth" data="1.5 2.25; 3 4"/>
  <module class="Constant" name="Plain" data="1 2; 3 4"/>
  <module class="GazeController" name="Gaze" target_override="yes" target="0.5 0.2 0.9"/>
  <module class="Constant" name="Target" data="0 0 0"/>
  <connection source="Target.OUTPUT" target="Gaze.INPUT"/>
  <view name="V">
    <image source="Gray.OUTPUT" format="gray" x="0" y="0" width="100" height="100"/>
  </view>
</group>"""
STORE = get_typestore(Stores.ROS2_HUMBLE)
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
TICKS = 4
TYPES = {"Colour": "sensor_msgs/msg/Image", "Gray": "sensor_msgs/msg/Image",
         "Depth": "sensor_msgs/msg/Image", "Gaze": "sensor_msgs/msg/JointState",
         "Plain": "std_msgs/msg/Float32MultiArray"}


@pytest.fixture
def recording(tmp_path):
    path = tmp_path / "m.ikg"
    path.write_text(MODEL)
    seen = {}
    with ikaros.load(str(path)) as net:
        rec = net.record(str(tmp_path / "run.mcap"), only=[f"{n}.OUTPUT" for n in TYPES],
                         images="Depth.OUTPUT", joint_states="Gaze.OUTPUT")
        for _ in range(TICKS):
            net.step()
            for name in ("Colour", "Gray", "Depth", "Plain", "Gaze"):
                seen[(name, net.tick - 1)] = net.output(f"{name}.OUTPUT")
        rec.close()
    return tmp_path / "run.mcap", seen


def _check(name, message, values):
    if name == "Colour":
        _, rows, cols = values.shape
        assert (message.encoding, message.height, message.width, message.step) == \
            ("rgb8", rows, cols, cols * 3)
        pixels = np.clip(np.rint(values * 255), 0, 255).astype(np.uint8).transpose(1, 2, 0)
        np.testing.assert_array_equal(message.data, pixels.reshape(-1))
    elif name in ("Gray", "Depth"):
        rows, cols = values.shape
        assert (message.encoding, message.height, message.width, message.step) == \
            ("32FC1", rows, cols, cols * 4)
        np.testing.assert_array_equal(message.data.view("<f4").reshape(rows, cols), values)
    elif name == "Gaze":
        assert list(message.name) == [f"Gaze.{k}" for k in range(4)]
        np.testing.assert_allclose(message.position, values.astype(np.float64) * math.pi / 180)
    else:
        np.testing.assert_array_equal(message.data, values.reshape(-1))


def test_images_and_joint_states_have_their_ros_types_in_the_file(recording):
    path, seen = recording
    got = {}
    with open(path, "rb") as f:
        reader = make_reader(f)
        for schema, channel, message in reader.iter_messages():
            name = channel.topic.split("/")[2]
            assert schema.name == TYPES[name]
            got[(name, message.sequence)] = STORE.deserialize_cdr(message.data, schema.name)
            qos = parse_qos(channel.metadata["offered_qos_profiles"])
            assert [(q.history.name, q.depth, q.reliability.name, q.durability.name,
                     q.liveliness.name) for q in qos] == \
                [("KEEP_LAST", 10, "RELIABLE", "VOLATILE", "AUTOMATIC")]
        metadata = {m.name: m.metadata for m in reader.iter_metadata()}
    assert sorted(got) == sorted(seen)
    for (name, tick), message in got.items():
        _check(name, message, seen[(name, tick)])
    assert metadata["outputs"]["Colour.OUTPUT"] == \
        "/ikaros/Colour/OUTPUT sensor_msgs/msg/Image rgb8"
    assert metadata["outputs"]["Gray.OUTPUT"] == "/ikaros/Gray/OUTPUT sensor_msgs/msg/Image 32FC1"
    assert metadata["outputs"]["Gaze.OUTPUT"] == \
        "/ikaros/Gaze/OUTPUT sensor_msgs/msg/JointState"
    assert metadata["outputs"]["Plain.OUTPUT"] == \
        "/ikaros/Plain/OUTPUT std_msgs/msg/Float32MultiArray"


def _read_bag(path) -> dict:
    got = {}
    with Reader(path) as reader:
        for connection in reader.connections:
            qos = connection.ext.offered_qos_profiles
            assert [q.reliability.name for q in qos] == ["RELIABLE"], connection.topic
        for connection, stamp, data in reader.messages():
            got.setdefault(connection.topic.split("/")[2], []).append(
                STORE.deserialize_cdr(data, connection.msgtype))
    return got


def test_rosbags_reads_the_file_and_its_rosbag2_conversion_alike(recording, tmp_path):
    path, seen = recording
    direct = _read_bag(path)
    bag = tmp_path / "bag"
    convert(srcs=[path], dst=bag, dst_storage="sqlite3", dst_version=8, compress=None,
            compress_mode="file", default_typestore=None, typestore=None, exclude_topics=[],
            include_topics=[], exclude_msgtypes=[], include_msgtypes=[])
    converted = _read_bag(bag)
    assert sorted(direct) == sorted(converted) == sorted(TYPES)
    for name, messages in converted.items():
        assert len(messages) == len(direct[name]) == TICKS
        for tick, message in enumerate(messages):
            _check(name, message, seen[(name, tick)])
    assert "offered_qos_profiles" in (bag / "metadata.yaml").read_text()


def test_ros_types_are_refused_for_hdf5_and_unmatched_patterns(tmp_path):
    path = tmp_path / "m.ikg"
    path.write_text(MODEL)
    with ikaros.load(str(path)) as net:
        with pytest.raises(ValueError, match="for MCAP recordings"):
            net.record(str(tmp_path / "run.h5"), images="Depth.OUTPUT")
        with pytest.raises(ValueError, match="joint_states: no recorded output matches "
                                             "'Arm.OUTPUT'"):
            net.record(str(tmp_path / "run.mcap"), joint_states="Arm.OUTPUT")


def test_a_vision_example_opens_as_images(tmp_path):
    pytest.importorskip("cv2")
    example = os.path.join(ROOT, "examples", "vision", "overhead_tracker.ikg")
    seen = []
    with ikaros.load(example) as net:
        rec = net.record(str(tmp_path / "run.mcap"), only=["Camera.OUTPUT", "RedMarker.OUTPUT"])
        for _ in range(2):
            net.step()
            seen.append((net.output("Camera.OUTPUT"), net.output("RedMarker.OUTPUT")))
        rec.close()
    with Reader(tmp_path / "run.mcap") as reader:
        types = {c.topic: c.msgtype for c in reader.connections}
        assert types == {"/ikaros/Camera/OUTPUT": "sensor_msgs/msg/Image",
                         "/ikaros/RedMarker/OUTPUT": "sensor_msgs/msg/Image"}
        messages = [(c.topic, STORE.deserialize_cdr(d, c.msgtype))
                    for c, _, d in reader.messages()]
    camera = [m for t, m in messages if t == "/ikaros/Camera/OUTPUT"]
    marker = [m for t, m in messages if t == "/ikaros/RedMarker/OUTPUT"]
    for (colour, gray), c, m in zip(seen, camera, marker):
        _check("Colour", c, colour)          # (3, 240, 320) as rgb8
        _check("Gray", m, gray)              # shown by the example's <image> as 32FC1
