"""Opening serial ports (real ones and the pseudo-terminals of the simulators) through pyserial."""
from __future__ import annotations

from typing import Any

from ikaros.hardware import DeviceError

INSTALL_HINT = "pip install 'ikaros[robots]'"


def require(module_name: str, purpose: str) -> Any:
    """Import an optional robot package or raise DeviceError with the pip command that installs it."""
    import importlib
    try:
        return importlib.import_module(module_name)
    except ImportError:
        raise DeviceError(f"{purpose} needs the Python package '{module_name}', which is not "
                          f"installed: {INSTALL_HINT}") from None


def open_serial(device: str, baudrate: int, timeout: float = 0.1, what: str = "serial device"):
    """Open ``device`` at ``baudrate`` (8N1, raw) and return the ``serial.Serial``.

    Failures raise :class:`DeviceError` naming ``what`` and the device, with the likely cause
    (missing device, no permission) instead of pyserial's bare OSError.
    """
    serial = require("serial", f"The {what}")
    try:
        return serial.Serial(device, baudrate=baudrate, timeout=timeout, write_timeout=max(timeout, 1.0))
    except serial.SerialException as error:
        raise DeviceError(f"cannot open the {what} at '{device}': {describe_error(error)}") from None
    except (OSError, ValueError) as error:
        raise DeviceError(f"cannot open the {what} at '{device}': {error}") from None


def describe_error(error: Exception) -> str:
    """Why a port could not be opened, with the likely fix."""
    number = getattr(error, "errno", None)
    text = str(error)
    if number == 2 or "No such file" in text:
        return "no such device (is it plugged in? see docs/robots.md for the device names)"
    if number == 13 or "Permission denied" in text:
        return "permission denied (add yourself to the 'dialout' group, see docs/robots.md)"
    return text


class SerialDevice:
    """A device on a serial port: opens it, and turns failed reads and writes into
    DeviceErrors naming the device (``the SSC-32 at '/dev/ttyUSB0' does not answer ...``).
    A driver sets ``what`` and builds its commands on :meth:`_write` and :meth:`_read`."""

    what = "serial device"

    def __init__(self, device: str, baud_rate: int, timeout: float):
        self.device = device
        self.timeout = timeout
        self.port = open_serial(device, baud_rate, timeout=timeout, what=self.what)

    def _write(self, data: bytes) -> None:
        try:
            self.port.write(data)
        except Exception as error:       # pyserial raises SerialException or OSError
            raise DeviceError(f"the {self.what} at '{self.device}' cannot be written to: "
                              f"{error}") from None

    def _read(self, count: int, what: str) -> bytes:
        """Exactly ``count`` bytes of the reply ``what``, or a DeviceError."""
        try:
            reply = self.port.read(count)
        except Exception as error:
            raise DeviceError(f"the {self.what} at '{self.device}' cannot be read: "
                              f"{error}") from None
        if len(reply) < count:
            raise DeviceError(f"the {self.what} at '{self.device}' does not answer ({what}: "
                              f"{len(reply)} of {count} bytes within {self.timeout} s)")
        return reply

    def close(self) -> None:
        """Close the port once everything written has gone out."""
        try:
            self.port.flush()
            self.port.close()
        except Exception:
            pass
