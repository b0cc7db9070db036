"""ROS 2 topics over DDS with Eclipse Cyclone DDS (``pip install 'ikaros[ros2]'``), named
and typed as rmw_cyclonedds (and ROS 2's other DDS middlewares) name them, so that ROS 2
nodes see them: the ROS topic ``/name`` is the DDS topic ``rt/name``, the message type
``pkg/msg/Type`` is the DDS type ``pkg::msg::dds_::Type_``, samples are XCDR1
little-endian, and ``ROS_DOMAIN_ID`` chooses the domain. Cyclone DDS reads its network
settings from ``CYCLONEDDS_URI`` as usual.

Samples are written and taken as CDR bytes (messages.py encodes them with NumPy); the types
declared here give DDS the names and the type information ROS 2 nodes match on.
"""

import os
import threading
import time
from dataclasses import dataclass

# (no "from __future__ import annotations": Cyclone DDS reads the types of the fields)
from cyclonedds._clayer import ddspy_take, ddspy_write
from cyclonedds.core import InstanceState, Listener, Policy, Qos, SampleState, ViewState
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import float32, float64, int32, sequence, uint8, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from .messages import MessageType

QOS_PROFILES = {
    # rmw_qos_profile_default: reliable, volatile, keep last 10
    "default": Qos(Policy.Reliability.Reliable(0), Policy.Durability.Volatile,
                   Policy.History.KeepLast(10)),
    # rmw_qos_profile_sensor_data: best effort, volatile, keep last 5
    "sensor_data": Qos(Policy.Reliability.BestEffort, Policy.Durability.Volatile,
                       Policy.History.KeepLast(5)),
}
_ANY = SampleState.Any | ViewState.Any | InstanceState.Any


# --- the types, as ROS 2 names them ------------------------------------------------------
@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str


@dataclass
class MultiArrayDimension(IdlStruct, typename="std_msgs::msg::dds_::MultiArrayDimension_"):
    label: str
    size: uint32
    stride: uint32


@dataclass
class MultiArrayLayout(IdlStruct, typename="std_msgs::msg::dds_::MultiArrayLayout_"):
    dim: sequence[MultiArrayDimension]
    data_offset: uint32


@dataclass
class Float32MultiArray(IdlStruct, typename="std_msgs::msg::dds_::Float32MultiArray_"):
    layout: MultiArrayLayout
    data: sequence[float32]


@dataclass
class Float64MultiArray(IdlStruct, typename="std_msgs::msg::dds_::Float64MultiArray_"):
    layout: MultiArrayLayout
    data: sequence[float64]


@dataclass
class Float32(IdlStruct, typename="std_msgs::msg::dds_::Float32_"):
    data: float32


@dataclass
class Float64(IdlStruct, typename="std_msgs::msg::dds_::Float64_"):
    data: float64


@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Twist(IdlStruct, typename="geometry_msgs::msg::dds_::Twist_"):
    linear: Vector3
    angular: Vector3


@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header
    name: sequence[str]
    position: sequence[float64]
    velocity: sequence[float64]
    effort: sequence[float64]


@dataclass
class Image(IdlStruct, typename="sensor_msgs::msg::dds_::Image_"):
    header: Header
    height: uint32
    width: uint32
    encoding: str
    is_bigendian: uint8
    step: uint32
    data: sequence[uint8]


IDL = {cls.__idl_typename__: cls for cls in (Float32MultiArray, Float64MultiArray, Float32,
                                              Float64, Twist, JointState, Image)}


# --- names and domain --------------------------------------------------------------------
def dds_topic(ros_topic: str) -> str:
    """The DDS topic of a ROS topic: ``/cmd_vel`` -> ``rt/cmd_vel``."""
    name = ros_topic.strip().lstrip("/")
    if not name or any(c.isspace() for c in name) or "//" in name:
        raise ValueError(f'"{ros_topic}" is not a ROS topic name (for example /cmd_vel)')
    return "rt/" + name


def domain_id(text: str | None = None) -> int:
    """The domain: ``text`` when given, else ``ROS_DOMAIN_ID``, else 0."""
    value = text if text not in (None, "") else os.environ.get("ROS_DOMAIN_ID", "0") or "0"
    if not str(value).strip().isdigit() or not 0 <= int(value) <= 232:
        raise ValueError(f'the ROS domain id "{value}" must be a whole number from 0 to 232')
    return int(value)


_participants: dict[int, DomainParticipant] = {}
_listeners: list = []
_lock = threading.Lock()


def participant(domain: int) -> DomainParticipant:
    """The process's participant in ``domain`` (one per domain, as a ROS 2 process has)."""
    with _lock:
        if domain not in _participants:
            _participants[domain] = DomainParticipant(domain)
        return _participants[domain]


def _topic(domain: int, ros_topic: str, kind: MessageType) -> Topic:
    return Topic(participant(domain), dds_topic(ros_topic), IDL[kind.dds_name])


# --- publishing and subscribing ----------------------------------------------------------
class Publisher:
    """Writes CDR bytes of ``kind`` to a ROS topic."""

    def __init__(self, ros_topic: str, kind: MessageType, qos: str = "default",
                 domain: int = 0):
        self.kind = kind
        self._writer = DataWriter(participant(domain), _topic(domain, ros_topic, kind),
                                  qos=QOS_PROFILES[qos])

    def publish(self, data: bytes) -> None:
        padded = data + b"\x00" * (-len(data) % 4)     # as Cyclone's own writer pads
        result = ddspy_write(self._writer._ref, padded)
        if result < 0:
            raise OSError(f"DDS refused the sample (return code {result})")

    def close(self) -> None:
        self._writer = None


class Subscription:
    """Keeps the latest sample of a ROS topic as it arrives (in Cyclone's thread), with
    the time it arrived; reading it never waits."""

    def __init__(self, ros_topic: str, kind: MessageType, qos: str = "default",
                 domain: int = 0):
        self.kind = kind
        self._latest: "tuple[bytes, float] | None" = None
        self._guard = threading.Lock()
        self.received = 0
        listener = Listener(on_data_available=self._arrived)
        # Cyclone DDS may call a listener from its own threads until a reader is deleted,
        # later than Python drops it: the listener (a C callback) lives as long as the process
        _listeners.append(listener)
        self._reader = DataReader(participant(domain), _topic(domain, ros_topic, kind),
                                  qos=QOS_PROFILES[qos], listener=listener)

    def _arrived(self, reader) -> None:
        if reader is None:          # a sample that arrived as the reader was deleted
            return
        now = time.monotonic()
        samples = ddspy_take(reader._ref, _ANY, 64)
        if isinstance(samples, int):
            return
        valid = [data for data, info in samples if info.valid_data]
        if valid:
            with self._guard:
                self._latest = (valid[-1], now)
                self.received += len(valid)

    def latest(self) -> "tuple[bytes, float] | None":
        """The latest sample's bytes and its arrival (``time.monotonic()``), or None."""
        with self._guard:
            return self._latest

    def close(self) -> None:
        """No more samples: the reader stops listening before it goes."""
        if self._reader is not None:
            self._reader.set_listener(None)
            self._reader = None
