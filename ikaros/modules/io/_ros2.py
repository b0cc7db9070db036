"""What the ROS 2 classes share: their parameters, the optional extra, and Ikaros images
to and from sensor_msgs/Image."""
from __future__ import annotations

import numpy as np

from ikaros.hardware.ros2.messages import message_type
from ikaros.module import Parameter, require

TYPE_NAMES = ["Float32MultiArray", "Float64MultiArray", "Float32", "Float64", "Twist",
              "JointState", "Image"]
PACKAGES = {"Twist": "geometry_msgs", "JointState": "sensor_msgs", "Image": "sensor_msgs"}
IMAGE_ENCODINGS = ["rgb8", "bgr8", "mono8", "32FC1"]


def topic_parameter() -> Parameter:
    return Parameter("/ikaros", "the ROS topic (/cmd_vel); the DDS topic is rt/ and the name",
                     fixed=True)


def type_parameter(default: str) -> Parameter:
    return Parameter(default, "the message type: std_msgs/Float32MultiArray, "
                     "Float64MultiArray, Float32, Float64, geometry_msgs/Twist, "
                     "sensor_msgs/JointState or sensor_msgs/Image", options=TYPE_NAMES,
                     fixed=True)


def qos_parameter() -> Parameter:
    return Parameter("default", "the QoS profile: default (reliable, volatile, keep last "
                     "10) or sensor_data (best effort, keep last 5), as ROS 2 defines them",
                     options=["default", "sensor_data"], fixed=True)


def domain_parameter() -> Parameter:
    return Parameter("", "the DDS domain; empty: the environment's ROS_DOMAIN_ID, else 0",
                     fixed=True)


def connect(module, kind_name: str):
    """The dds module (or the error with the pip install that fixes it), the message type,
    and the domain, for a module's parameters; errors name the module."""
    dds = require("ikaros.hardware.ros2.dds", "cyclonedds", extra="ros2")
    kind = message_type(f"{PACKAGES.get(kind_name, 'std_msgs')}/msg/{kind_name}")
    try:
        dds.dds_topic(module.topic)
        domain = dds.domain_id(module.domain_id)
    except ValueError as error:
        raise ValueError(f"{module.path}: {error}") from None
    return dds, kind, domain


def image_message(values: np.ndarray, encoding: str) -> tuple[int, int, int, bytes]:
    """An Ikaros image ((rows, cols) or (3, rows, cols), 0..1) as (height, width, step,
    data) of a sensor_msgs/Image in ``encoding``."""
    if encoding == "32FC1":
        plane = values if values.ndim == 2 else values.mean(axis=0)
        data = np.ascontiguousarray(plane, "<f4")
        return plane.shape[0], plane.shape[1], plane.shape[1] * 4, data.tobytes()
    scaled = np.clip(np.rint(values * 255.0), 0, 255).astype(np.uint8)
    if encoding == "mono8":
        plane = scaled if scaled.ndim == 2 else np.rint(values.mean(axis=0) * 255.0).clip(
            0, 255).astype(np.uint8)
        return plane.shape[0], plane.shape[1], plane.shape[1], plane.tobytes()
    planes = scaled if scaled.ndim == 3 else np.stack([scaled] * 3)
    if encoding == "bgr8":
        planes = planes[::-1]
    pixels = np.ascontiguousarray(planes.transpose(1, 2, 0))
    return pixels.shape[0], pixels.shape[1], pixels.shape[1] * 3, pixels.tobytes()


def image_values(message: dict, out: np.ndarray) -> str | None:
    """Write a sensor_msgs/Image into the Ikaros image ``out``; an error text when it cannot
    (another size or encoding)."""
    rows, cols, encoding = message["height"], message["width"], message["encoding"]
    if (rows, cols) != out.shape[-2:]:
        return f"an image of {cols}x{rows} came, {out.shape[-1]}x{out.shape[-2]} was expected"
    data = np.frombuffer(message["data"], np.uint8)
    step = message["step"]
    if encoding in ("rgb8", "bgr8"):
        pixels = data.reshape(rows, step)[:, :cols * 3].reshape(rows, cols, 3) / 255.0
        planes = pixels.transpose(2, 0, 1)
        if encoding == "bgr8":
            planes = planes[::-1]
        out[...] = planes if out.ndim == 3 else planes.mean(axis=0)
    elif encoding == "mono8":
        plane = data.reshape(rows, step)[:, :cols] / 255.0
        out[...] = plane if out.ndim == 2 else plane[None]
    elif encoding == "32FC1":
        plane = data.reshape(rows, step)[:, :cols * 4].copy().view("<f4")
        out[...] = plane if out.ndim == 2 else plane[None]
    else:
        return f'the image encoding "{encoding}" is not supported ({", ".join(IMAGE_ENCODINGS)})'
    return None
