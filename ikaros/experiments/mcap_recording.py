"""Recording a run into an MCAP file as ROS 2 messages, for Foxglove, ``ros2 bag play`` and
rosbags (``ikaros --record run.mcap``; needs ``pip install 'ikaros[ros2]'``).

Each recorded output is a topic ``/ikaros/<its address with / for .>`` of ROS 2 messages
(schema encoding ``ros2msg``, message encoding ``cdr``): images as sensor_msgs/msg/Image,
joint positions asked for as sensor_msgs/msg/JointState, any other output as
std_msgs/msg/Float32MultiArray whose layout gives its shape (ros_outputs.py says which is
which). A message's ``sequence`` is its tick and its log and publish times are the model's
time (tick × tick_duration) after the wall-clock time the recording started. Each channel
carries the QoS profile it was offered with (``offered_qos_profiles``, as rosbag2 writes it,
so that ``ros2 bag play`` replays with it). The model file's text is an attachment
(``model.ikg``), the parameters' values are metadata (``parameters``), and so is which
output is which topic and type (``outputs``). The outputs are taken by an output tap as
for HDF5 recordings (recording.py); a writer thread encodes and writes them. The HDF5
recording stays the one to analyse runs with (``ikaros.open_recording``).
"""
from __future__ import annotations

import atexit
import os
import queue
import threading
import time

import numpy as np

from .. import priority
from ..hardware.ros2.msgdefs import DEFINITIONS
from ..kernel.taps import ROW, SIGNAL
from ..module import FATAL_ERROR, WARNING, require
from .recording import FLUSH_SECONDS
from .ros_outputs import ros_outputs
from .signals import model_text, module_parameters, select_outputs
from .writefaults import check_on_error, failure_text, remove_recording

BLOCK_ROWS = 1024
# The QoS a recorded topic was offered with, as rosbag2 writes a channel's
# offered_qos_profiles (YAML, enums as numbers): keep last 10, reliable, volatile, automatic
# liveliness, no deadline, lifespan or lease (rmw's "infinite": 2147483647 s 4294967295 ns).
_INFINITE = "{sec: 2147483647, nsec: 4294967295}"
OFFERED_QOS = (f"- history: 1\n  depth: 10\n  reliability: 1\n  durability: 2\n"
               f"  deadline: {_INFINITE}\n  lifespan: {_INFINITE}\n  liveliness: 1\n"
               f"  liveliness_lease_duration: {_INFINITE}\n"
               f"  avoid_ros_namespace_conventions: false")


class McapRecorder:
    """Records outputs of a network into an MCAP file, every ``every``-th tick from the next
    tick on, until ``close()`` (or the network's ``close()``); ``only``, ``flush_seconds``
    and ``on_error`` as for Recorder (writefaults.py). Unlike an HDF5 recording, an MCAP file
    whose writing failed (a full disk) is not kept: its last chunk and its index are lost, so
    it is removed and the message says so."""

    def __init__(self, net, filename: str, only: list[str] | str | None = None,
                 every: int = 1, command_line: list[str] | None = None,
                 flush_seconds: float = FLUSH_SECONDS, on_error: str = "stop",
                 images: list[str] | str = (), joint_states: list[str] | str = ()):
        mcap_writer = require("mcap.writer", "mcap", extra="ros2")
        self.on_error = check_on_error(on_error)
        if int(every) < 1:
            raise ValueError(f"every must be a whole number >= 1, not {every}")
        self.net = net
        self.filename = os.path.abspath(filename)
        self.every = int(every)
        self.flush_seconds = flush_seconds
        self.signals, index = select_outputs(net, only)
        self.outputs = ros_outputs(net, self.signals, _patterns(images), _patterns(joint_states))
        try:
            self._file = open(self.filename, "wb")
        except OSError as e:
            raise OSError(f"cannot write the recording {filename}: {e.strerror}") from None
        self._writer = mcap_writer.Writer(self._file)
        self._start(net, command_line)
        self._rows = np.zeros((BLOCK_ROWS, max(index.size, 1)), np.float32)[:, :index.size]
        self._rows = np.ascontiguousarray(self._rows)
        self._queue: queue.Queue = queue.Queue()
        self._error: BaseException | None = None
        self._reported = False
        self._closed = False
        self.ticks_recorded = 0
        self._thread = threading.Thread(target=self._write_loop, name="ikaros-mcap",
                                        daemon=True)
        self._thread.start()
        self._tap = net.add_tap(index, self._rows, self.every, self._signalled)
        self._tap.give(0, BLOCK_ROWS)
        net.close_hooks.append(self.close)
        atexit.register(self.close)

    def _start(self, net, command_line) -> None:
        w = self._writer
        w.start(profile="ros2", library="ikaros")
        schemas = {t: w.register_schema(t, "ros2msg", DEFINITIONS[t].encode())
                   for t in dict.fromkeys(o.type for o in self.outputs)}
        self._channels = [w.register_channel(o.topic, "cdr", schemas[o.type],
                                             {"offered_qos_profiles": OFFERED_QOS})
                          for o in self.outputs]
        self._wall = time.time_ns()
        w.add_attachment(self._wall, self._wall, "model.ikg", "application/xml",
                         model_text(net).encode("utf-8"))
        w.add_metadata("parameters", module_parameters(net))
        w.add_metadata("outputs", {o.address: o.description() for o in self.outputs})
        w.add_metadata("ikaros", {"file": net.filename or "", "tick_duration":
                                  repr(net.clock.tick_duration),
                                  "command_line": " ".join(command_line or [])})

    @property
    def closed(self) -> bool:
        return self._closed

    def _signalled(self) -> None:
        """The tap's call back (at the start of a tick): hand the rows kept to the writer
        and give the block again."""
        tap = self._tap
        if self._error is not None:
            tap.stop()
            if not self._reported:
                self._reported = True
                self.net.notify(WARNING if self.on_error == "continue" else FATAL_ERROR,
                                None, self.failure)
            return
        tap.state[SIGNAL] = 0
        row = int(tap.state[ROW])
        if row:
            self._queue.put((self._rows[:row].copy(), tap.ticks[:row].copy()))
        tap.give(0, BLOCK_ROWS)

    def _write_loop(self) -> None:
        priority.background_thread()
        due = time.monotonic() + self.flush_seconds
        dt_ns = self.net.clock.tick_duration * 1e9
        while True:
            try:
                item = self._queue.get(timeout=max(0.01, due - time.monotonic()))
            except queue.Empty:
                self._tap.request()
                due = time.monotonic() + self.flush_seconds
                continue
            if item is None:
                return
            if self._error is not None:
                continue
            rows, ticks = item
            try:
                for values, tick in zip(rows, ticks):
                    stamp = self._wall + int(round(int(tick) * dt_ns))
                    seconds = int(tick) * self.net.clock.tick_duration
                    for signal, channel, output in zip(self.signals, self._channels,
                                                       self.outputs):
                        data = output.encode(values[signal.start:signal.stop], seconds)
                        self._writer.add_message(channel, stamp, data, stamp, int(tick))
                    self.ticks_recorded += 1
            except Exception as e:      # noqa: BLE001  (a full disk): the run is told
                remove_recording(self.filename)     # now: a cut MCAP file is no use
                self._error = e
                self._tap.request()

    @property
    def failure(self) -> str | None:
        """Why writing failed and what the file holds (None while it has not failed)."""
        if self._error is None:
            return None
        return failure_text(self.filename, self._error, 0, None, None, self.on_error)

    def close(self, complete: bool = True) -> None:
        """Write what is left and end the file, with metadata ``run``: ``finished`` (false
        for a run cut off, ``complete=False``) and ``ticks_recorded``. Call it between
        ticks."""
        if self._closed:
            return
        self._closed = True
        atexit.unregister(self.close)
        if self.close in self.net.close_hooks:
            self.net.close_hooks.remove(self.close)
        self._tap.settle()
        self._signalled()
        self.net.remove_tap(self._tap)
        self._queue.put(None)
        self._thread.join()
        try:
            if self._error is None:
                self._writer.add_metadata("run", {
                    "finished": "true" if complete else "false",
                    "ticks_recorded": str(self.ticks_recorded)})
                self._writer.finish()
        except OSError as e:
            self._error = e
        finally:
            self._file.close()
        if self._error is not None:
            remove_recording(self.filename)
            if self.on_error == "stop":
                raise OSError(self.failure)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def _patterns(value: list[str] | str) -> list[str]:
    return [value] if isinstance(value, str) else list(value or ())
