"""The SSC-32 protocol at the byte level, its simulator, and the driver against the simulator."""
from __future__ import annotations

import time

import pytest

from ikaros.hardware import DeviceError
from ikaros.hardware.serial_port import open_serial
from ikaros.hardware.ssc32 import (SSC32, decode_pulses, move_command,
                                   query_pulse_command)
from ikaros.hardware.ssc32_sim import VERSION, VirtualSSC32


def test_move_command_bytes():
    assert move_command({0: 1500}, 1000) == b"#0P1500T1000\r"
    assert move_command({0: 1500, 3: 900}, speeds={3: 500}) == b"#0P1500#3P900S500\r"
    assert move_command({5: 2500, 31: 500}, 20, {5: 100, 31: 200}) == \
        b"#5P2500S100#31P500S200T20\r"
    assert move_command({1: 0, 2: 0}) == b"#1P0#2P0\r"


@pytest.mark.parametrize("pulses, time_ms, message", [
    ({0: 499}, None, "outside 500..2500"), ({0: 2501}, None, "outside 500..2500"),
    ({32: 1500}, None, "channel 32"), ({}, None, "at least one"),
    ({0: 1500}, 65536, "1..65535")])
def test_move_command_refuses_bad_values(pulses, time_ms, message):
    with pytest.raises(ValueError, match=message):
        move_command(pulses, time_ms)


def test_query_and_reply_bytes():
    assert query_pulse_command([0, 3, 17]) == b"QP 0 QP 3 QP 17\r"
    assert decode_pulses(bytes([150, 50, 250, 0]), 4) == [1500, 500, 2500, 0]
    with pytest.raises(ValueError, match="2 of 3 bytes"):
        decode_pulses(bytes([150, 150]), 3)
    with pytest.raises(ValueError, match="byte 255"):
        decode_pulses(bytes([150, 255]), 2)


@pytest.fixture
def board():
    with VirtualSSC32() as device:
        port = open_serial(device.path, 115200, timeout=1.0, what="SSC-32")
        yield device, port
        port.close()


def test_simulator_answers_raw_bytes(board):
    device, port = board
    port.write(b"#0P1500\r#4P2000\r")
    port.write(b"QP 0 QP 4 QP 9\r")
    assert port.read(3) == bytes([150, 200, 0])         # channel 9 has no pulses
    port.write(b"VER\r")
    assert port.read_until(b"\r") == VERSION.encode() + b"\r"
    port.write(b"Q\r")
    assert port.read(1) == b"."
    assert device.commands == ["#0P1500", "#4P2000", "QP 0 QP 4 QP 9", "VER", "Q"]


def test_simulated_moves_are_linear_in_time(board):
    device, port = board
    port.write(b"#0P1000\r")
    port.write(b"#0P2000#1P1200T400\r")      # channel 1 was off: it jumps
    port.write(b"Q\r")
    assert port.read(1) == b"+"
    channel = device.channels[0]
    t0 = channel.t0
    assert channel.t1 - t0 == pytest.approx(0.4)
    assert device.pulse(0, t0 + 0.1) == pytest.approx(1250)
    assert device.pulse(0, t0 + 0.3) == pytest.approx(1750)
    assert device.pulse(0, t0 + 0.5) == 2000
    assert device.pulse(1, t0 + 0.1) == 1200
    # a speed limit: 1000 µs at 500 µs/s takes 2 s, longer than T
    port.write(b"#1P2200S500T100\r")
    time.sleep(0.05)
    assert device.channels[1].t1 - device.channels[1].t0 == pytest.approx(2.0)
    port.write(b"STOP 0 STOP 1\r")
    time.sleep(0.05)
    port.write(b"Q\r")
    assert port.read(1) == b"."


def test_driver_moves_reads_back_and_turns_off():
    with VirtualSSC32() as device:
        ssc = SSC32(device.path)
        try:
            assert ssc.version() == VERSION
            ssc.move({0: 1500, 2: 800}, time_ms=100)
            assert ssc.moving()
            time.sleep(0.15)
            assert not ssc.moving()
            assert ssc.pulse_widths([0, 2, 5]) == [1500, 800, 0]
            ssc.off([0, 2])
            assert ssc.pulse_widths([0, 2]) == [0, 0]
            assert device.commands[-2] == "#0P0#2P0"
        finally:
            ssc.close()


def test_driver_reports_a_silent_board_with_its_port():
    with VirtualSSC32(fault="silent") as device:
        ssc = SSC32(device.path, timeout=0.1)
        try:
            ssc.move({0: 1500})
            with pytest.raises(DeviceError, match=f"SSC-32 at '{device.path}' does not answer"):
                ssc.pulse_widths([0])
            with pytest.raises(DeviceError, match="does not answer"):
                ssc.version()
        finally:
            ssc.close()


def test_driver_reports_corrupted_replies():
    with VirtualSSC32(fault="corrupt") as device:
        ssc = SSC32(device.path, timeout=0.1)
        try:
            ssc.move({0: 1500, 1: 1500})
            with pytest.raises(DeviceError, match="corrupted reply to the pulse width query"):
                ssc.pulse_widths([0, 1])
            with pytest.raises(DeviceError, match="corrupted reply to the movement query"):
                ssc.moving()
        finally:
            ssc.close()


def test_driver_reports_a_board_that_disappears():
    device = VirtualSSC32().start()
    ssc = SSC32(device.path, timeout=0.1)
    try:
        device.disconnect()
        with pytest.raises(DeviceError, match="SSC-32"):
            ssc.move({0: 1500})
            ssc.pulse_widths([0])
    finally:
        ssc.close()
        device.stop()


def test_a_missing_port_is_named():
    with pytest.raises(DeviceError, match="cannot open the SSC-32 at '/dev/no-such-ssc32'"):
        SSC32("/dev/no-such-ssc32")
