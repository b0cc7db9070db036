"""A simulated serial device on a pseudo-terminal: the shared base of the device simulators.

The simulator holds the master side of a pseudo-terminal (``os.openpty()``, raw mode); a driver
opens the slave side, :attr:`PtyDevice.path` (e.g. ``/dev/pts/7``), exactly as it would open
``/dev/ttyUSB0``. A reader thread hands every chunk of bytes the driver writes to
:meth:`PtyDevice.received`; the simulator answers with :meth:`PtyDevice.send`. Chunks are as
they arrive (a packet may come in pieces, or several in one chunk), so a simulator keeps its
own input buffer and parses complete packets from it.

How another simulator uses it::

    from ikaros.hardware.pty_device import PtyDevice

    class EchoUpper(PtyDevice):
        name = "echo"                       # used in thread names and messages

        def __init__(self):
            super().__init__()
            self.pending = bytearray()

        def received(self, data: bytes) -> None:       # runs in the reader thread
            self.pending += data
            while b"\\r" in self.pending:
                line, _, rest = bytes(self.pending).partition(b"\\r")
                self.pending = bytearray(rest)
                self.send(line.upper() + b"\\r")

    with EchoUpper() as device:             # start() ... stop()
        port = serial.Serial(device.path, 115200, timeout=0.5)
        port.write(b"hello\\r"); assert port.read(6) == b"HELLO\\r"

``stop()`` ends the reader thread within about 0.1 s and closes both sides; it is safe to call
twice. ``disconnect()`` simulates a device that is unplugged (the driver's next read or write
fails); ``baudrate`` (optional) makes :meth:`send` take the time the bytes would take on a real
line of that speed (10 bits a byte). Simulators are meant for tests and demonstrations on this
machine; they never touch a real device.
"""
from __future__ import annotations

import logging
import os
import select
import threading
import time
import tty

log = logging.getLogger(__name__)

_POLL_SECONDS = 0.05
_WRITE_TIMEOUT = 1.0


class PtyDevice:
    """Base class of a simulated serial device; override :meth:`received`."""

    name = "device"

    def __init__(self, baudrate: int | None = None):
        self.baudrate = baudrate
        self._master: int | None = None
        self._slave: int | None = None
        self._path = ""
        self._thread: threading.Thread | None = None
        self._stopping = threading.Event()
        self._write_lock = threading.Lock()

    # --- to override -------------------------------------------------------------------------

    def received(self, data: bytes) -> None:
        """Handle bytes the driver wrote (called in the reader thread)."""
        raise NotImplementedError

    # --- life cycle ---------------------------------------------------------------------------

    @property
    def path(self) -> str:
        """The device path a driver opens (valid after :meth:`start`)."""
        if not self._path:
            raise RuntimeError(f"the {self.name} simulator is not started")
        return self._path

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def start(self) -> "PtyDevice":
        """Open the pseudo-terminal and start answering; returns self."""
        if self._master is not None:
            return self
        master, slave = os.openpty()
        tty.setraw(slave)           # no echo, no line editing, no CR/LF translation
        tty.setraw(master)
        os.set_blocking(master, False)
        self._master, self._slave = master, slave
        self._path = os.ttyname(slave)
        self._stopping.clear()
        self._thread = threading.Thread(target=self._read_loop, name=f"{self.name}-sim", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        """Stop answering and close the pseudo-terminal (bounded: about 0.1 s)."""
        self._end_reading()
        self._thread = None
        self._close()

    def disconnect(self) -> None:
        """Fault: the device disappears; the driver's reads and writes fail from now on (when
        this returns: the reader thread has ended before the terminal is closed, so no read
        of it races the close)."""
        self._end_reading()
        self._close()

    def _end_reading(self) -> None:
        self._stopping.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)

    def __enter__(self) -> "PtyDevice":
        return self.start()

    def __exit__(self, *exc_info) -> None:
        self.stop()

    # --- talking ------------------------------------------------------------------------------

    def transfer_seconds(self, byte_count: int) -> float:
        """Time ``byte_count`` bytes take on the simulated line (0 without a baud rate)."""
        return byte_count * 10.0 / self.baudrate if self.baudrate else 0.0

    def send(self, data: bytes) -> None:
        """Write ``data`` to the driver (after the simulated line time, if a baud rate is set)."""
        delay = self.transfer_seconds(len(data))
        if delay:
            sleep_until(time.perf_counter() + delay)
        with self._write_lock:
            view = memoryview(data)
            deadline = time.monotonic() + _WRITE_TIMEOUT
            while view and self._master is not None:
                try:
                    written = os.write(self._master, view)
                    view = view[written:]
                except BlockingIOError:         # nobody reads the other side: wait, then drop
                    if time.monotonic() > deadline:
                        return
                    select.select([], [self._master], [], _POLL_SECONDS)
                except OSError:
                    return

    def _read_loop(self) -> None:
        while not self._stopping.is_set():
            master = self._master
            if master is None:
                return
            try:
                ready, _, _ = select.select([master], [], [], _POLL_SECONDS)
                if not ready:
                    continue
                data = os.read(master, 4096)
            except BlockingIOError:
                continue
            except (OSError, ValueError):       # closed under us (stop or disconnect)
                if self._stopping.is_set():
                    return
                time.sleep(_POLL_SECONDS)       # EIO while no driver holds the port open
                continue
            if data:
                try:
                    self.received(data)
                except Exception:               # a simulator bug must not kill the device silently
                    log.exception("the %s simulator failed on %r", self.name, data[:64])

    def _close(self) -> None:
        for fd in (self._master, self._slave):
            if fd is not None:
                try:
                    os.close(fd)
                except OSError:
                    pass
        self._master = self._slave = None


def sleep_until(deadline: float) -> None:
    """Wait until ``time.perf_counter()`` reaches ``deadline``: sleep, then spin for the last
    0.2 ms (a sleep may overshoot by about 0.1 ms)."""
    while True:
        remaining = deadline - time.perf_counter()
        if remaining <= 0:
            return
        if remaining > 0.0003:
            time.sleep(remaining - 0.0002)
