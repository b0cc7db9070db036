"""Messages in ROS 2's CDR encoding: byte for byte what rosbags (an independent
implementation of ROS 2 CDR) writes for the same message, and read back from its bytes."""
import numpy as np
import pytest
import rosbags.typesys as rosbags        # an independent implementation of ROS 2 CDR

from ikaros.hardware.ros2.cdr import CdrError
from ikaros.hardware.ros2.msgdefs import DEFINITIONS
from ikaros.hardware.ros2.messages import (TYPES, float32_array_encoder, layout_of,
                                           message_type, stamp)

STORE = rosbags.get_typestore(rosbags.Stores.ROS2_HUMBLE)
T = STORE.types


def _theirs(name, message) -> bytes:
    return bytes(STORE.serialize_cdr(message, name))


def _header(sec, nanosec, frame):
    return T["std_msgs/msg/Header"](stamp=T["builtin_interfaces/msg/Time"](sec=sec,
                                                                            nanosec=nanosec),
                                    frame_id=frame)


def _multi_array(name, dtype, shape, labels=()):
    data = (np.arange(int(np.prod(shape))) * 1.5 - 2).astype(dtype)
    layout = layout_of(shape, labels)
    dims = [T["std_msgs/msg/MultiArrayDimension"](**d) for d in layout["dim"]]
    theirs = T[name](layout=T["std_msgs/msg/MultiArrayLayout"](dim=dims, data_offset=0),
                     data=data)
    return {"layout": layout, "data": data}, theirs


CASES = {
    "float32": ("std_msgs/msg/Float32", {"data": 1.25},
                lambda: T["std_msgs/msg/Float32"](data=1.25)),
    "float64": ("std_msgs/msg/Float64", {"data": -3.5e-7},
                lambda: T["std_msgs/msg/Float64"](data=-3.5e-7)),
    "twist": ("geometry_msgs/msg/Twist", {"linear": (0.5, 0, 0), "angular": (0, 0, -1.25)},
              lambda: T["geometry_msgs/msg/Twist"](
                  linear=T["geometry_msgs/msg/Vector3"](x=0.5, y=0.0, z=0.0),
                  angular=T["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=-1.25))),
    "joint_state": ("sensor_msgs/msg/JointState",
                    {"header": {"stamp": (12, 500_000_000), "frame_id": "base_link"},
                     "name": ["shoulder", "elbow", "wrist_roll"],
                     "position": np.array([0.1, -0.2, 0.3]), "velocity": np.array([]),
                     "effort": np.array([1.0, 2.0, 3.0])},
                    lambda: T["sensor_msgs/msg/JointState"](
                        header=_header(12, 500_000_000, "base_link"),
                        name=["shoulder", "elbow", "wrist_roll"],
                        position=np.array([0.1, -0.2, 0.3]), velocity=np.array([], np.float64),
                        effort=np.array([1.0, 2.0, 3.0]))),
    "joint_state_empty": ("sensor_msgs/msg/JointState",
                          {"header": {"stamp": (0, 0), "frame_id": ""}, "name": [],
                           "position": [], "velocity": [], "effort": []},
                          lambda: T["sensor_msgs/msg/JointState"](
                              header=_header(0, 0, ""), name=[],
                              position=np.array([], np.float64),
                              velocity=np.array([], np.float64),
                              effort=np.array([], np.float64))),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_message_is_encoded_as_rosbags_encodes_it(case):
    name, ours, theirs = CASES[case]
    assert TYPES[name].encode(ours) == _theirs(name, theirs())


@pytest.mark.parametrize("name, dtype, shape, labels", [
    ("std_msgs/msg/Float32MultiArray", np.float32, (16,), ()),
    ("std_msgs/msg/Float32MultiArray", np.float32, (2, 3), ("rows", "cols")),
    ("std_msgs/msg/Float32MultiArray", np.float32, (0,), ()),
    ("std_msgs/msg/Float64MultiArray", np.float64, (3, 4, 5), ("a", "bb", "ccc")),
    ("std_msgs/msg/Float32MultiArray", np.float32, (480, 640), ()),
])
def test_multi_arrays_with_their_layout(name, dtype, shape, labels):
    ours, theirs = _multi_array(name, dtype, shape, labels)
    data = TYPES[name].encode(ours)
    assert data == _theirs(name, theirs)
    back = TYPES[name].decode(data)
    assert back["layout"] == ours["layout"]
    np.testing.assert_array_equal(back["data"], ours["data"])


@pytest.mark.parametrize("encoding, channels, dtype", [
    ("rgb8", 3, np.uint8), ("bgr8", 3, np.uint8), ("mono8", 1, np.uint8),
    ("32FC1", 1, np.float32)])
def test_images_of_each_encoding(encoding, channels, dtype):
    rows, cols = 48, 64
    pixels = (np.arange(rows * cols * channels) % 251).astype(dtype)
    step = cols * channels * np.dtype(dtype).itemsize
    ours = {"header": {"stamp": stamp(3.25), "frame_id": "camera"}, "height": rows,
            "width": cols, "encoding": encoding, "is_bigendian": 0, "step": step,
            "data": pixels.tobytes()}
    theirs = T["sensor_msgs/msg/Image"](header=_header(3, 250_000_000, "camera"), height=rows,
                                        width=cols, encoding=encoding, is_bigendian=0,
                                        step=step, data=np.frombuffer(pixels.tobytes(),
                                                                      np.uint8))
    data = TYPES["sensor_msgs/msg/Image"].encode(ours)
    assert data == _theirs("sensor_msgs/msg/Image", theirs)
    back = TYPES["sensor_msgs/msg/Image"].decode(data)
    assert bytes(back.pop("data")) == ours.pop("data")
    assert back == ours


@pytest.mark.parametrize("case", sorted(CASES))
def test_their_bytes_are_read_back(case):
    name, ours, theirs = CASES[case]
    back = TYPES[name].decode(_theirs(name, theirs()))
    for key, value in ours.items():
        if isinstance(value, (list, np.ndarray)) and key != "name":
            np.testing.assert_array_equal(back[key], value)
        elif key in ("linear", "angular"):
            assert back[key] == tuple(float(v) for v in value)
        else:
            assert back[key] == value


def test_a_long_string_and_a_large_name_list():
    names = [f"joint_{i}_" + "x" * i for i in range(200)]
    ours = {"header": {"stamp": (1, 2), "frame_id": "f" * 1000}, "name": names,
            "position": np.linspace(-1, 1, 200), "velocity": [], "effort": []}
    theirs = T["sensor_msgs/msg/JointState"](header=_header(1, 2, "f" * 1000), name=names,
                                             position=np.linspace(-1, 1, 200),
                                             velocity=np.array([], np.float64),
                                             effort=np.array([], np.float64))
    assert TYPES["sensor_msgs/msg/JointState"].encode(ours) == \
        _theirs("sensor_msgs/msg/JointState", theirs)


def test_types_are_named_as_ros_2_names_them():
    assert message_type("std_msgs/Float32").dds_name == "std_msgs::msg::dds_::Float32_"
    assert message_type("sensor_msgs/msg/Image").name == "sensor_msgs/msg/Image"
    with pytest.raises(KeyError, match='"nav_msgs/Odometry" is not supported'):
        message_type("nav_msgs/Odometry")


def test_truncated_bytes_are_an_error_not_garbage():
    data = TYPES["std_msgs/msg/Float64"].encode({"data": 1.0})
    with pytest.raises(CdrError, match="the message ends after 4 bytes; 8 were needed"):
        TYPES["std_msgs/msg/Float64"].decode(data[:8])
    with pytest.raises(CdrError, match="not little-endian CDR"):
        TYPES["std_msgs/msg/Float64"].decode(b"\x00\x00\x00\x00" + data[4:])


@pytest.mark.parametrize("shape", [(1,), (16,), (2, 3), (3, 4, 5), (0,)])
def test_the_fast_array_encoder_writes_what_the_message_encoder_writes(shape):
    values = (np.arange(int(np.prod(shape))) * 0.5 - 1).astype(np.float32).reshape(shape)
    full = TYPES["std_msgs/msg/Float32MultiArray"].encode({"layout": layout_of(shape),
                                                           "data": values})
    assert float32_array_encoder(shape)(values) == full


@pytest.mark.parametrize("case", sorted(CASES))
def test_each_definition_reads_our_bytes_in_rosbags(case):
    """The .msg text Foxglove and MCAP files are given describes the bytes we write."""
    name, ours, _ = CASES[case]
    store = rosbags.get_typestore(rosbags.Stores.EMPTY)
    store.register(rosbags.get_types_from_msg(DEFINITIONS[name], name))
    back = store.deserialize_cdr(TYPES[name].encode(ours), name)
    assert back.__msgtype__ == name


@pytest.mark.parametrize("name", ["std_msgs/msg/Float32MultiArray",
                                  "std_msgs/msg/Float64MultiArray", "sensor_msgs/msg/Image"])
def test_the_array_and_image_definitions_read_our_bytes_in_rosbags(name):
    store = rosbags.get_typestore(rosbags.Stores.EMPTY)
    store.register(rosbags.get_types_from_msg(DEFINITIONS[name], name))
    if name == "sensor_msgs/msg/Image":
        message = {"header": {"stamp": (1, 2), "frame_id": "cam"}, "height": 2, "width": 3,
                   "encoding": "mono8", "is_bigendian": 0, "step": 3, "data": bytes(range(6))}
        back = store.deserialize_cdr(TYPES[name].encode(message), name)
        assert (back.height, back.width, bytes(back.data)) == (2, 3, bytes(range(6)))
    else:
        message = {"layout": layout_of((2, 2)), "data": np.arange(4)}
        back = store.deserialize_cdr(TYPES[name].encode(message), name)
        np.testing.assert_array_equal(back.data, np.arange(4))
        assert [(d.size, d.stride) for d in back.layout.dim] == [(2, 4), (2, 2)]
