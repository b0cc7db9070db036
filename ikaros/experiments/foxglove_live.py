"""A running model's outputs live in Foxglove (``ikaros --foxglove [PORT]``; needs
``pip install 'ikaros[foxglove]'``).

The outputs are served on Foxglove's WebSocket protocol (through foxglove-sdk) on 127.0.0.1,
one channel per output, named as in MCAP recordings (``/ikaros/Arm/Joint/OUTPUT``) and
encoded the same way (std_msgs/msg/Float32MultiArray in ROS 2's CDR, with the ``ros2msg``
schema), so Foxglove shows them next to a robot's own ROS 2 topics. Values are sent after a
tick at most ``interval`` seconds apart (default 0.05: 20 updates a second), and only while
a client listens.
"""
from __future__ import annotations

import time

import numpy as np

from ..hardware.ros2.messages import float32_array_encoder
from ..hardware.ros2.msgdefs import DEFINITIONS
from ..module import require
from .mcap_recording import MESSAGE, topic_of
from .signals import select_outputs

DEFAULT_PORT = 8765
DEFAULT_INTERVAL = 0.05


class FoxgloveView:
    """Serves the outputs of ``net`` to Foxglove from its controller's tick hooks until
    ``close()`` (or the network's ``close()``)."""

    def __init__(self, net, port: int = DEFAULT_PORT, host: str = "127.0.0.1",
                 interval: float = DEFAULT_INTERVAL, only: list[str] | str | None = None):
        foxglove = require("foxglove", "foxglove-sdk", extra="foxglove")
        self.net = net
        self.interval = float(interval)
        self.signals, self._index = select_outputs(net, only)
        self._context = foxglove.Context()
        schema = foxglove.Schema(name=MESSAGE, encoding="ros2msg",
                                 data=DEFINITIONS[MESSAGE].encode())
        self.channels = [foxglove.Channel(topic_of(s.name), schema=schema,
                                          message_encoding="cdr", context=self._context)
                         for s in self.signals]
        self._encoders = [float32_array_encoder(s.shape) for s in self.signals]
        self.server = foxglove.start_server(name=f"ikaros {net.filename or ''}".strip(),
                                            host=host, port=port, context=self._context)
        self.port = self.server.port
        self._sent = 0.0
        self._wall = time.time_ns() - int(net.clock.time * 1e9)
        net.controller.tick_hooks.append(self._tick)
        net.close_hooks.append(self.close)

    def _tick(self) -> None:
        now = time.perf_counter()
        if now - self._sent < self.interval or not self.channels[0:1] \
                or not any(c.has_sinks() for c in self.channels):
            return
        self._sent = now
        values = np.take(self.net.arena.block, self._index)
        stamp = self._wall + int(self.net.clock.time * 1e9)
        for signal, channel, encode in zip(self.signals, self.channels, self._encoders):
            channel.log(encode(values[signal.start:signal.stop]), log_time=stamp)

    def close(self) -> None:
        """Stop serving."""
        hooks = self.net.controller.tick_hooks
        if self._tick in hooks:
            hooks.remove(self._tick)
        if self.close in self.net.close_hooks:
            self.net.close_hooks.remove(self.close)
        self.server.stop()
