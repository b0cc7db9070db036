"""The pseudo-terminal base of the simulators and the serial-port opener."""
from __future__ import annotations

import os
import time

import pytest
import serial

from ikaros.hardware import DeviceError
from ikaros.hardware.pty_device import PtyDevice
from ikaros.hardware.serial_port import SerialDevice, open_serial, require


class EchoUpper(PtyDevice):
    name = "echo"

    def __init__(self, baudrate=None):
        super().__init__(baudrate)
        self.pending = bytearray()

    def received(self, data: bytes) -> None:
        self.pending += data
        while b"\r" in self.pending:
            line, _, rest = bytes(self.pending).partition(b"\r")
            self.pending = bytearray(rest)
            self.send(line.upper() + b"\r")


def test_a_driver_talks_to_the_simulator_through_the_slave_path():
    with EchoUpper() as device:
        assert device.path.startswith("/dev/pts/")
        port = open_serial(device.path, 115200, timeout=1.0, what="echo box")
        try:
            port.write(b"hel")
            port.write(b"lo\rbye\r")          # pieces and two lines in one write
            assert port.read(10) == b"HELLO\rBYE\r"
        finally:
            port.close()


def test_stop_is_bounded_and_closes_the_terminal():
    device = EchoUpper().start()
    path = device.path
    begun = time.monotonic()
    device.stop()
    device.stop()
    assert time.monotonic() - begun < 0.5
    assert not device.running
    assert not os.path.exists(path)


def test_disconnect_makes_the_driver_fail():
    with EchoUpper() as device:
        port = open_serial(device.path, 115200, timeout=0.2)
        device.disconnect()
        assert not device.running           # the reader has ended: nothing reads the closed terminal
        with pytest.raises((serial.SerialException, OSError)):
            port.write(b"x\r")
            port.read(2)
        port.close()


class EchoBox(SerialDevice):
    what = "echo box"


def test_a_serial_device_names_itself_in_every_failure():
    with EchoUpper() as device:
        box = EchoBox(device.path, 115200, timeout=0.1)
        box._write(b"ab\r")
        assert box._read(3, "echo") == b"AB\r"
        with pytest.raises(DeviceError) as silent:
            box._write(b"cd")                       # no end of line: no reply
            box._read(3, "echo")
        assert str(silent.value) == (f"the echo box at '{device.path}' does not answer "
                                     "(echo: 0 of 3 bytes within 0.1 s)")
        box.close()
        with pytest.raises(DeviceError, match=f"the echo box at '{device.path}' cannot be "
                                              "written to: "):
            box._write(b"x\r")
        with pytest.raises(DeviceError, match=f"the echo box at '{device.path}' cannot be "
                                              "read: "):
            box._read(1, "echo")


def test_baudrate_delays_replies_by_the_line_time():
    with EchoUpper(baudrate=9600) as device:     # 10 bytes take 10.4 ms
        port = open_serial(device.path, 9600, timeout=1.0)
        begun = time.perf_counter()
        port.write(b"abcdefghi\r")
        assert port.read(10) == b"ABCDEFGHI\r"
        assert time.perf_counter() - begun >= 10 * 10 / 9600
        port.close()


def test_opening_a_missing_device_names_it():
    with pytest.raises(DeviceError) as caught:
        open_serial("/dev/ttyNOSUCH0", 57600, what="Dynamixel bus")
    assert str(caught.value).startswith("cannot open the Dynamixel bus at '/dev/ttyNOSUCH0': no such device")


def test_a_missing_package_gives_the_pip_command():
    with pytest.raises(DeviceError, match=r"pip install 'ikaros\[robots\]'"):
        require("no_such_package_xyz", "The test")
