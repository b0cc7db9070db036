"""A running model live in Foxglove (``ikaros --foxglove [PORT]``; needs
``pip install 'ikaros[foxglove]'``).

The model is served on Foxglove's WebSocket protocol (through foxglove-sdk) on 127.0.0.1,
as ROS 2 messages in ROS 2's CDR with their ``ros2msg`` schemas, so Foxglove shows them next
to a robot's own ROS 2 topics:

* every output on a channel named and typed as in MCAP recordings
  (``/ikaros/Arm/Joint/OUTPUT``; ros_outputs.py): images as sensor_msgs/msg/Image for
  Foxglove's image panel, any other output as a std_msgs/msg/Float32MultiArray whose layout
  gives its shape, for plots;
* what each ROS2Publisher of the model publishes (a JointState, a Twist, an Image, ...) on
  its own topic and with its own type, so the joint states a model sends a robot show in
  Foxglove's 3D and state panels.

Values are sent after a tick at most ``interval`` seconds apart (default 0.05: 20 updates a
second), and only while a client listens. Clients that name the protocol
``foxglove.sdk.v1`` (Foxglove today) and those that name it ``foxglove.websocket.v1``
(older Foxglove and Lichtblick versions) are both admitted.
"""
from __future__ import annotations

import time

import numpy as np

from ..hardware.ros2.msgdefs import DEFINITIONS
from ..module import require
from .foxglove_subprotocol import SubprotocolFront
from .ros_outputs import ros_outputs
from .signals import select_outputs

DEFAULT_PORT = 8765
DEFAULT_INTERVAL = 0.05


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
        self._outputs = [(s, channel(o.topic, o.type), o.encode)      # (signal, channel, encode)
                         for s, o in zip(self.signals, ros_outputs(net, self.signals))]
        self._publishers = [(inst.module, channel(inst.module.topic, inst.module.message_type))
                            for inst in net.modules.values()
                            if getattr(inst.module, "message_type", "")]
        self.channels = [c for _, c, _ in self._outputs] + [c for _, c in self._publishers]
        self._last_sent: list = [None] * len(self._publishers)    # each publisher's
        # the SDK's server on a loopback port of its own, behind a front on the view's port
        # that also admits clients of the protocol's old name (foxglove_subprotocol.py)
        self.server = foxglove.start_server(name=f"ikaros {net.filename or ''}".strip(),
                                            host="127.0.0.1", port=0, context=self._context)
        try:
            self._front = SubprotocolFront(self.server.port, host, port)
        except OSError:
            self.server.stop()
            raise
        self.port = self._front.port
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
            channel.log(encode(values[signal.start:signal.stop], self.net.clock.time),
                        log_time=at)
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
        self._front.close()
        self.server.stop()
