"""A simulated Touch Board on a pseudo-terminal: writes DataStream lines as the board does.

Minimal and self-contained; it belongs on the shared simulated-serial-device base
(ikaros/hardware/pty_device.py) once that is merged.
"""
from __future__ import annotations

import os
import threading
import tty

from .touchboard import LABELS, format_line

ELECTRODES = 13


class SimulatedTouchBoard:
    """Opens a pseudo-terminal whose other end (``port``) a program opens as the board's
    serial port, and writes every kind of DataStream line every ``interval`` seconds.
    ``set(label, values)`` changes what is written."""

    def __init__(self, interval: float = 0.01):
        self.master, slave = os.openpty()
        tty.setraw(slave)
        self.port = os.ttyname(slave)
        self._slave = slave
        self.values = {label: [0] * ELECTRODES for label in LABELS}
        self.lock = threading.Lock()
        self.interval = interval
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def set(self, label: str, values) -> None:
        with self.lock:
            self.values[label] = list(values)

    def _run(self) -> None:
        while not self._stop.wait(self.interval):
            with self.lock:
                data = b"".join(format_line(k, v) for k, v in self.values.items())
            try:
                os.write(self.master, data)
            except OSError:
                return

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2)
        os.close(self.master)
        os.close(self._slave)
