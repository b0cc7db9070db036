"""ROS2Subscriber: the latest message of a ROS 2 topic, never waiting for one."""
import time

import numpy as np

from ikaros.hardware.ros2.images import image_values
from ikaros.module import Module, Output, Parameter

from ._ros2 import (connect, domain_parameter, qos_parameter, topic_parameter,
                    type_parameter)

SHAPES = {"Float32": "1", "Float64": "1", "Twist": "6"}


class ROS2Subscriber(Module):
    """Subscribes to the ROS 2 topic ``topic`` (message ``type``) through DDS (Eclipse
    Cyclone DDS: ``pip install 'ikaros[ros2]'``; no ROS installation is needed) and outputs
    the latest message. A tick never waits: messages are taken as they arrive, and OUTPUT
    keeps the last one until a newer one comes. AGE says how old it is (seconds since it
    arrived; before the first, since the module started) and STALE is 1 when none has come
    for ``stale_after`` seconds (or none yet), as the cameras do. What OUTPUT holds:
    Float32MultiArray and Float64MultiArray: the first ``size`` values (a message with fewer
    leaves the rest 0, with a warning); Float32 and Float64: the value; Twist: linear x, y, z
    and angular x, y, z; JointState: the positions of the joints named in ``names`` in that
    order (of the first ``size`` joints when ``names`` is empty), with VELOCITY and EFFORT;
    Image: a (rows, cols) gray or (3, rows, cols) colour image of ``width`` × ``height`` in
    0..1 (rgb8, bgr8, mono8; 32FC1 as it is). See docs/ros2.md. This class is not part of the
    original Ikaros."""

    topic = topic_parameter()
    type = type_parameter("Float32MultiArray")
    qos = qos_parameter()
    domain_id = domain_parameter()
    size = Parameter(1, "Float32MultiArray, Float64MultiArray, JointState: how many values "
                     "(joints) OUTPUT holds", type="int", range=(1, None), fixed=True)
    names = Parameter("", "JointState: the joints to output, by name, separated by commas",
                      fixed=True)
    width = Parameter(640, "Image: the width of OUTPUT", type="int", range=(1, None),
                      fixed=True)
    height = Parameter(480, "Image: the height of OUTPUT", type="int", range=(1, None),
                       fixed=True)
    color = Parameter(True, "Image: a colour (3, rows, cols) OUTPUT, else gray (rows, cols)",
                      fixed=True)
    stale_after = Parameter(0.5, "seconds without a message after which STALE is 1",
                            range=(0, None))

    OUTPUT = Output("the latest message's values (see the class description)")
    VELOCITY = Output("JointState: the joints' velocities (else 0)")
    EFFORT = Output("JointState: the joints' efforts (else 0)")
    AGE = Output("seconds since the latest message arrived (since the start before the "
                 "first)", size="1")
    STALE = Output("1 when no message has come for stale_after seconds, or none yet",
                   size="1")
    RECEIVED = Output("messages received so far", size="1")

    def set_sizes(self):
        names = [n.strip() for n in str(self.names).split(",") if n.strip()]
        count = len(names) if self.type == "JointState" and names else int(self.size)
        if self.type == "Image":
            shape = (3, self.height, self.width) if self.color else (self.height, self.width)
        else:
            shape = (int(SHAPES.get(self.type, count)),)
        self.set_output_shape("OUTPUT", shape)
        joints = count if self.type == "JointState" else 0
        self.set_output_shape("VELOCITY", (joints,))
        self.set_output_shape("EFFORT", (joints,))

    def configure(self):
        connect(self, self.type)        # a missing extra or a bad topic fails the load

    def init(self):
        dds, self._kind, domain = connect(self, self.type)
        self._names = [n.strip() for n in str(self.names).split(",") if n.strip()]
        self._subscription = dds.Subscription(self.topic, self._kind, self.qos, domain)
        self._seen = None           # the arrival time of the message on the outputs
        self._started = time.monotonic()
        self._warned = set()
        self._take = {"Float32MultiArray": self._array, "Float64MultiArray": self._array,
                      "Float32": self._scalar, "Float64": self._scalar, "Twist": self._twist,
                      "JointState": self._joint_state, "Image": self._image}[self.type]

    def tick(self):
        latest = self._subscription.latest()
        now = time.monotonic()
        if latest is not None and latest[1] != self._seen:
            data, self._seen = latest
            try:
                self._take(self._kind.decode(data))
            except ValueError as error:     # bytes that are not this type
                self._warn_once("decode", f"a message on {self.topic} is not a "
                                          f"{self._kind.name}: {error}")
        age = now - (self._started if self._seen is None else self._seen)
        self.AGE[0] = age
        self.STALE[0] = 1.0 if self._seen is None or age > self.stale_after else 0.0
        self.RECEIVED[0] = self._subscription.received

    def stop(self):
        self._subscription.close()

    def _warn_once(self, key: str, text: str) -> None:
        if key not in self._warned:
            self._warned.add(key)
            self.warning(text)

    def _fill(self, out: np.ndarray, values) -> None:
        values = np.asarray(values, np.float64).reshape(-1)
        n = min(out.size, values.size)
        out.reshape(-1)[:n] = values[:n]
        out.reshape(-1)[n:] = 0.0
        if values.size < out.size:
            self._warn_once("size", f"a message on {self.topic} has {values.size} values; "
                                    f"{out.size} were expected (the rest are 0)")

    def _array(self, message: dict) -> None:
        self._fill(self.OUTPUT, message["data"])

    def _scalar(self, message: dict) -> None:
        self.OUTPUT[0] = message["data"]

    def _twist(self, message: dict) -> None:
        self.OUTPUT[:] = list(message["linear"]) + list(message["angular"])

    def _joint_state(self, message: dict) -> None:
        if self._names:
            where = {name: i for i, name in enumerate(message["name"])}
            missing = [n for n in self._names if n not in where]
            if missing:
                self._warn_once("joints", f"a JointState on {self.topic} lacks the joints "
                                          f"{', '.join(missing)} (they stay as they were)")
            index = [(k, where[n]) for k, n in enumerate(self._names) if n in where]
        else:
            index = [(k, k) for k in range(min(self.OUTPUT.size, len(message["position"])))]
        for out, field in ((self.OUTPUT, "position"), (self.VELOCITY, "velocity"),
                           (self.EFFORT, "effort")):
            values = message[field]
            for k, i in index:
                if i < len(values):
                    out[k] = values[i]

    def _image(self, message: dict) -> None:
        problem = image_values(message, self.OUTPUT)
        if problem:
            self._warn_once("image", f"{self.topic}: {problem}")
