"""What the ROS 2 classes share: their parameters and the optional extra."""
from __future__ import annotations

from ikaros.hardware.ros2.messages import message_type
from ikaros.module import Parameter, require

TYPE_NAMES = ["Float32MultiArray", "Float64MultiArray", "Float32", "Float64", "Twist",
              "JointState", "Image"]
PACKAGES = {"Twist": "geometry_msgs", "JointState": "sensor_msgs", "Image": "sensor_msgs"}


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
