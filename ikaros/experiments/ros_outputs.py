"""How an output goes to ROS tools (MCAP recordings, the live Foxglove view): the ROS 2
message type it is sent as, and its encoder.

- a colour image, an output of shape (3, rows, cols): ``sensor_msgs/msg/Image``, rgb8;
- a gray image, an output of shape (rows, cols) that a view of the model shows as an image
  (an Ikaros 2 ``<image>`` or an Ikaros 3 ``<widget class="image">``) or that ``images``
  names: ``sensor_msgs/msg/Image``, 32FC1 (the values exactly);
- joint positions named by ``joint_states``: ``sensor_msgs/msg/JointState``, in radians
  (from the module's ``angle_unit`` when it has one: degrees, radians or tau), the joints
  named ``<module>.<element>``;
- any other output: ``std_msgs/msg/Float32MultiArray`` whose layout gives its shape.

Messages with a header carry the model's time (tick × tick_duration) and frame id
``ikaros``.
"""
from __future__ import annotations

import fnmatch
import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..hardware.ros2.images import image_message
from ..hardware.ros2.messages import TYPES, float32_array_encoder, stamp
from ..kernel.tree import ModuleInstance, find_component

ARRAY = "std_msgs/msg/Float32MultiArray"
IMAGE = "sensor_msgs/msg/Image"
JOINT_STATE = "sensor_msgs/msg/JointState"
FRAME = "ikaros"
RADIANS_PER = {"degrees": math.pi / 180, "radians": 1.0, "tau": 2 * math.pi}


def topic_of(address: str) -> str:
    """The topic of an output: ``Arm.Joint.OUTPUT`` -> ``/ikaros/Arm/Joint/OUTPUT``."""
    return "/ikaros/" + address.replace(".", "/")


@dataclass(frozen=True)
class RosOutput:
    """One output as ROS tools get it: ``encode(values, seconds)`` gives a message's CDR
    bytes from the output's values (flat) at the model's time ``seconds``."""
    address: str
    topic: str
    type: str
    encoding: str            # an image's encoding, else ""
    encode: Callable[[np.ndarray, float], bytes]

    def description(self) -> str:
        """What the recording's metadata say of it: topic, type and (for images) encoding."""
        return " ".join(p for p in (self.topic, self.type, self.encoding) if p)


def _image(shape: tuple, encoding: str):
    def encode(values: np.ndarray, seconds: float) -> bytes:
        height, width, step, data = image_message(values.reshape(shape), encoding)
        return TYPES[IMAGE].encode({"header": {"stamp": stamp(seconds), "frame_id": FRAME},
                                    "height": height, "width": width, "encoding": encoding,
                                    "is_bigendian": 0, "step": step, "data": data})
    return encode


def _joint_state(names: list[str], scale: float):
    def encode(values: np.ndarray, seconds: float) -> bytes:
        return TYPES[JOINT_STATE].encode({
            "header": {"stamp": stamp(seconds), "frame_id": FRAME}, "name": names,
            "position": np.asarray(values, np.float64) * scale,
            "velocity": np.zeros(0), "effort": np.zeros(0)})
    return encode


def _array(shape: tuple):
    encode = float32_array_encoder(shape)
    return lambda values, seconds: encode(values)


def view_images(net) -> set[str]:
    """The addresses of the outputs that the model's views show as images."""
    found = set()
    groups = [net.top]
    while groups:
        group = groups.pop()
        groups += [c for c in group.children.values() if not isinstance(c, ModuleInstance)]
        for view in group.views:
            widgets = [view] if view.tag == "widget" else list(view.elements())
            for w in widgets:
                kind = w.get("class") if w.tag in ("widget", "object") else w.tag
                if (kind or "").replace("_", "").replace("-", "").lower() != "image":
                    continue
                for source in (w.get("source") or "").split(","):
                    module, _, output = source.strip().rpartition(".")
                    found_module = find_component(group, module) if module else None
                    if isinstance(found_module, ModuleInstance):
                        found.add(f"{found_module.path}.{output}")
    return found


def _matches(address: str, patterns) -> bool:
    return any(fnmatch.fnmatchcase(address, p) for p in patterns)


def ros_outputs(net, signals, images=(), joint_states=()) -> list[RosOutput]:
    """How each recorded output (experiments.signals.Signal) goes to ROS tools; ``images``
    and ``joint_states``: glob patterns of the outputs to send as gray images and as joint
    states (a pattern that matches no output is a ValueError)."""
    for patterns, what in ((images, "images"), (joint_states, "joint_states")):
        unmatched = [p for p in patterns if not any(fnmatch.fnmatchcase(s.name, p)
                                                    for s in signals)]
        if unmatched:
            raise ValueError(f'{what}: no recorded output matches '
                             f'{", ".join(repr(p) for p in unmatched)}')
    shown = view_images(net)
    out = []
    for s in signals:
        topic = topic_of(s.name)
        if _matches(s.name, joint_states):
            module = s.name.rsplit(".", 1)[0]
            try:
                unit = str(net.parameter(f"{module}.angle_unit"))
            except KeyError:
                unit = "radians"
            names = [f"{module}.{k}" for k in range(math.prod(s.shape))]
            out.append(RosOutput(s.name, topic, JOINT_STATE, "",
                                 _joint_state(names, RADIANS_PER.get(unit, 1.0))))
        elif len(s.shape) == 3 and s.shape[0] == 3:
            out.append(RosOutput(s.name, topic, IMAGE, "rgb8", _image(s.shape, "rgb8")))
        elif len(s.shape) == 2 and (s.name in shown or _matches(s.name, images)):
            out.append(RosOutput(s.name, topic, IMAGE, "32FC1", _image(s.shape, "32FC1")))
        else:
            out.append(RosOutput(s.name, topic, ARRAY, "", _array(s.shape)))
    return out
