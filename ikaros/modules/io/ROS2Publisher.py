"""ROS2Publisher: publishes an input on a ROS 2 topic every tick."""
import numpy as np

from ikaros.hardware.ros2.images import IMAGE_ENCODINGS, image_message
from ikaros.hardware.ros2.messages import layout_of, stamp
from ikaros.module import Input, Module, Parameter

from ._ros2 import (connect, domain_parameter, qos_parameter,
                    topic_parameter, type_parameter)


class ROS2Publisher(Module):
    """Publishes INPUT on the ROS 2 topic ``topic`` every tick, as the message ``type``,
    through DDS (Eclipse Cyclone DDS: ``pip install 'ikaros[ros2]'``), named so that ROS 2
    nodes on the same domain and network see it; no ROS installation is needed. What INPUT
    becomes: Float32MultiArray and Float64MultiArray: all its values, with a layout giving its
    shape (row-major); Float32 and Float64: its first value; Twist: linear x, y, z and angular
    x, y, z (6 values; missing ones are 0); JointState: the positions, with VELOCITY and EFFORT
    when connected and the joint names of ``names``; Image: a gray (rows, cols) or colour
    (3, rows, cols) image in 0..1, sent in ``encoding``. Messages with a header (JointState,
    Image) carry the model's time (tick × tick_duration) and ``frame_id``. Nothing is
    published before data from the sources has reached the inputs (a robot is not sent a
    command the model did not give). See docs/ros2.md. This class is not part of the
    original Ikaros."""

    topic = topic_parameter()
    type = type_parameter("Float32MultiArray")
    qos = qos_parameter()
    domain_id = domain_parameter()
    frame_id = Parameter("", "the frame id in the header of JointState and Image messages")
    names = Parameter("", "JointState: the joint names, separated by commas (one per "
                      "position)", fixed=True)
    encoding = Parameter("rgb8", "Image: the encoding sent", options=IMAGE_ENCODINGS,
                         fixed=True)

    # What the last tick published (the message type's ROS name and its bytes), for views of
    # the run: the live Foxglove view shows it on the same topic.
    message_type: str = ""
    last_message: bytes | None = None

    INPUT = Input("the values to publish")
    VELOCITY = Input("JointState: the joint velocities", optional=True)
    EFFORT = Input("JointState: the joint efforts", optional=True)

    def configure(self):
        connect(self, self.type)        # a missing extra or a bad topic fails the load

    def init(self):
        dds, self._kind, domain = connect(self, self.type)
        self._names = [n.strip() for n in str(self.names).split(",") if n.strip()]
        if self.type == "JointState" and self._names and len(self._names) != self.INPUT.size:
            raise ValueError(f"{self.path}: names lists {len(self._names)} joints but INPUT "
                             f"has {self.INPUT.size} positions")
        if self.type == "Image" and self.INPUT.ndim not in (2, 3):
            raise ValueError(f"{self.path}: an Image needs INPUT of shape (rows, cols) or "
                             f"(3, rows, cols), not {self.INPUT.shape}")
        self._first = self.start_steps()[1]
        self._publisher = dds.Publisher(self.topic, self._kind, self.qos, domain)
        self.message_type = self._kind.name
        self._encode = {"Float32MultiArray": self._array, "Float64MultiArray": self._array,
                        "Float32": self._scalar, "Float64": self._scalar,
                        "Twist": self._twist, "JointState": self._joint_state,
                        "Image": self._image}[self.type]

    def tick(self):
        if self._first is None or self.clock.tick < self._first:
            return
        self.last_message = self._kind.encode(self._encode())
        self._publisher.publish(self.last_message)

    def stop(self):
        self._publisher.close()

    def _header(self) -> dict:
        return {"stamp": stamp(self.clock.time), "frame_id": str(self.frame_id)}

    def _array(self) -> dict:
        return {"layout": layout_of(self.INPUT.shape), "data": self.INPUT}

    def _scalar(self) -> dict:
        return {"data": self.INPUT.reshape(-1)[0] if self.INPUT.size else 0.0}

    def _twist(self) -> dict:
        values = np.zeros(6)
        flat = self.INPUT.reshape(-1)[:6]
        values[:flat.size] = flat
        return {"linear": values[:3], "angular": values[3:]}

    def _joint_state(self) -> dict:
        return {"header": self._header(), "name": self._names,
                "position": self.INPUT.reshape(-1),
                "velocity": () if self.VELOCITY is None else self.VELOCITY.reshape(-1),
                "effort": () if self.EFFORT is None else self.EFFORT.reshape(-1)}

    def _image(self) -> dict:
        height, width, step, data = image_message(self.INPUT, self.encoding)
        return {"header": self._header(), "height": height, "width": width,
                "encoding": self.encoding, "is_bigendian": 0, "step": step, "data": data}
