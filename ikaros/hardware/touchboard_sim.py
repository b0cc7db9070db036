"""A simulated Touch Board on a pseudo-terminal: writes DataStream lines as the board does.

Built on :class:`ikaros.hardware.pty_device.PtyDevice`::

    with SimulatedTouchBoard() as board:
        board.set("FDAT", range(600, 613))
        ... open board.path as the board's serial port ...
"""
from __future__ import annotations

import threading

from .pty_device import PtyDevice
from .touchboard import LABELS, format_line

ELECTRODES = 13


class SimulatedTouchBoard(PtyDevice):
    """Writes every kind of DataStream line every ``interval`` seconds while started;
    ``set(label, values)`` changes what is written. What a driver sends is ignored, as the
    board's DataStream firmware does."""

    name = "touchboard"

    def __init__(self, interval: float = 0.01):
        super().__init__()
        self.interval = interval
        self.values = {label: [0] * ELECTRODES for label in LABELS}
        self._values_lock = threading.Lock()
        self._halt = threading.Event()
        self._streamer: threading.Thread | None = None

    def set(self, label: str, values) -> None:
        with self._values_lock:
            self.values[label] = list(values)

    def received(self, data: bytes) -> None:
        pass

    def start(self) -> "SimulatedTouchBoard":
        super().start()
        if self._streamer is None:
            self._halt.clear()
            self._streamer = threading.Thread(target=self._stream, name="touchboard-sim-stream",
                                              daemon=True)
            self._streamer.start()
        return self

    def stop(self) -> None:
        self._halt.set()            # the streamer ends before the pseudo-terminal closes
        if self._streamer is not None:
            self._streamer.join(timeout=2.0)
            self._streamer = None
        super().stop()

    def _stream(self) -> None:
        while not self._halt.wait(self.interval):
            with self._values_lock:
                data = b"".join(format_line(label, values) for label, values in self.values.items())
            self.send(data)
