"""Device protocols (serial ports, Dynamixel buses, SSC-32, e-puck, OPC) and their simulators.

Nothing here knows the kernel: robot modules use these classes, and so can any script.
Simulated serial devices share :mod:`ikaros.hardware.pty_device`; real and simulated ports
are opened with :func:`ikaros.hardware.serial_port.open_serial`.
"""
from __future__ import annotations


class DeviceError(Exception):
    """A device cannot be opened, stops answering, or answers wrongly.

    The message names the device (and the servo or channel, where there is one).
    """
