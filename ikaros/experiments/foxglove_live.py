"""A running model live in Foxglove (``ikaros --foxglove [PORT]``; needs
``pip install 'ikaros[foxglove]'``).

The model is served on Foxglove's WebSocket protocol (through foxglove-sdk) on 127.0.0.1,
as ROS 2 messages in ROS 2's CDR with their ``ros2msg`` schemas, so Foxglove shows them next
to a robot's own ROS 2 topics:

* every output on a channel named as in MCAP recordings (``/ikaros/Arm/Joint/OUTPUT``): a
  colour image, an output of shape (3, rows, cols), as a sensor_msgs/msg/Image (rgb8), for
  Foxglove's image panel; any other output as a std_msgs/msg/Float32MultiArray whose layout
  gives its shape, for plots;
* what each ROS2Publisher of the model publishes (a JointState, a Twist, an Image, ...) on
  its own topic and with its own type, so the joint states a model sends a robot show in
  Foxglove's 3D and state panels.

Values are sent after a tick at most ``interval`` seconds apart (default 0.05: 20 updates a
second), and only while a client listens.
"""
from __future__ import annotations

import time
from typing import Callable

import numpy as np

from ..hardware.ros2.images import image_message
from ..hardware.ros2.messages import TYPES, float32_array_encoder, stamp
from ..hardware.ros2.msgdefs import DEFINITIONS
from ..module import require
from .mcap_recording import MESSAGE, topic_of
from .signals import select_outputs

DEFAULT_PORT = 8765
DEFAULT_INTERVAL = 0.05
IMAGE = "sensor_msgs/msg/Image"


def _image_encoder(shape: tuple[int, ...], clock) -> Callable[[np.ndarray], bytes]:
    """Colour images (3, rows, cols) as rgb8 sensor_msgs/Image messages at the model's time."""
    def encode(values: np.ndarray) -> bytes:
        height, width, step, data = image_message(values.reshape(shape), "rgb8")
        return TYPES[IMAGE].encode({"header": {"stamp": stamp(clock.time),
                                               "frame_id": "ikaros"},
                                    "height": height, "width": width, "encoding": "rgb8",
                                    "is_bigendian": 0, "step": step, "data": data})
    return encode


class FoxgloveView:
    """Serves ``net`` to Foxglove from its controller's tick hooks until ``close()`` (or
    the network's ``close()``); ``only`` chooses outputs as for recordings."""

    def __init__(self, net, port: int = DEFAULT_PORT, host: str = "127.0.0.1",
                 interval: float = DEFAULT_INTERVAL, only: list[str] | str | None = None):
        foxglove = require("foxglove", "foxglove-sdk", extra="foxglove")
        self.net = net
        self.interval = float(interval)
        self.signals, self._index = select_outputs(net, only)
        self._context = foxglove.Context()

        def channel(topic: str, message_type: str):
            schema = foxglove.Schema(name=message_type, encoding="ros2msg",
                                     data=DEFINITIONS[message_type].encode())
            return foxglove.Channel(topic, schema=schema, message_encoding="cdr",
                                    context=self._context)
        self._outputs = []          # (signal, channel, encode)
        for s in self.signals:
            image = len(s.shape) == 3 and s.shape[0] == 3
            self._outputs.append((s, channel(topic_of(s.name), IMAGE if image else MESSAGE),
                                  _image_encoder(s.shape, net.clock) if image
                                  else float32_array_encoder(s.shape)))
        self._publishers = [(inst.module, channel(inst.module.topic, inst.module.message_type))
                            for inst in net.modules.values()
                            if getattr(inst.module, "message_type", "")]
        self.channels = [c for _, c, _ in self._outputs] + [c for _, c in self._publishers]
        self._last_sent: list = [None] * len(self._publishers)    # each publisher's
        self.server = foxglove.start_server(name=f"ikaros {net.filename or ''}".strip(),
                                            host=host, port=port, context=self._context)
        self.port = self.server.port
        self._sent = 0.0
        self._wall = time.time_ns() - int(net.clock.time * 1e9)
        net.controller.tick_hooks.append(self._tick)
        net.close_hooks.append(self.close)

    def _tick(self) -> None:
        now = time.perf_counter()
        if now - self._sent < self.interval or not any(c.has_sinks() for c in self.channels):
            return
        self._sent = now
        values = np.take(self.net.arena.block, self._index)
        at = self._wall + int(self.net.clock.time * 1e9)
        for signal, channel, encode in self._outputs:
            channel.log(encode(values[signal.start:signal.stop]), log_time=at)
        for k, (module, channel) in enumerate(self._publishers):
            message = module.last_message
            if message is not None and message is not self._last_sent[k]:
                self._last_sent[k] = message
                channel.log(message, log_time=at)

    def close(self) -> None:
        """Stop serving."""
        hooks = self.net.controller.tick_hooks
        if self._tick in hooks:
            hooks.remove(self._tick)
        if self.close in self.net.close_hooks:
            self.net.close_hooks.remove(self.close)
        self.server.stop()
