"""The UM7 binary protocol at the byte level, as the UM7 Datasheet (rev. 1.6, "Binary packet
structure") gives it: 's' 'n' 'p', the packet type (bit 7 has data, bit 6 is batch, bits
5..2 batch length), the address, 4 bytes per register (most significant first) and the
unsigned 16-bit sum of all the bytes before, high byte first; Euler angles are int16 counts
of 1/91.02222 degree. The expected bytes are written out here; the simulator is checked
against them through a real serial port on its pseudo-terminal."""
from __future__ import annotations

import math
import struct
import time

import pytest

from ikaros.hardware import um7
from ikaros.hardware.serial_port import open_serial
from ikaros.hardware.um7_sim import FIRMWARE, VirtualUM7

SNP = [0x73, 0x6E, 0x70]


def with_sum(body: list[int]) -> bytes:
    total = sum(body)
    return bytes(body + [(total >> 8) & 0xFF, total & 0xFF])


def test_read_requests_are_the_datasheets_packets():
    # a batch read of 8 registers from 0x61: packet type 0b0110_0000
    assert um7.read_request(0x61, 8) == with_sum(SNP + [0x60, 0x61])
    assert um7.read_request(0x61, 8).hex(" ") == "73 6e 70 60 61 02 12"
    assert um7.read_request(0x70) == with_sum(SNP + [0x00, 0x70])
    with pytest.raises(ValueError, match="1 to 15 registers"):
        um7.read_request(0x61, 16)


def test_a_write_of_one_register_and_a_batch():
    assert um7.packet(0x04, bytes([0, 0, 0, 20])) == with_sum(SNP + [0x80, 0x04, 0, 0, 0, 20])
    data = bytes(range(8))
    assert um7.packet(0x61, data) == with_sum(SNP + [0xC8, 0x61, *data])


def test_the_parser_takes_packets_in_pieces_and_skips_noise_and_bad_sums():
    good = with_sum(SNP + [0xC8, 0x70, 0, 1, 2, 3, 4, 5, 6, 7])
    bad = bytearray(with_sum(SNP + [0x80, 0x71, 9, 9, 9, 9]))
    bad[-1] ^= 0x55
    stream = b"\x00sn" + good + bytes(bad) + good
    parser = um7.PacketParser()
    found = []
    for k in range(0, len(stream), 3):
        found += parser.feed(stream[k:k + 3])
    assert [(p.packet_type, p.address, p.data) for p in found] == \
        [(0xC8, 0x70, bytes(range(8)))] * 2
    assert parser.bad == 1
    assert found[0].registers() == {0x70: bytes([0, 1, 2, 3]), 0x71: bytes([4, 5, 6, 7])}


@pytest.fixture
def sensor():
    with VirtualUM7(roll=10.0, pitch=-5.0, yaw=30.0) as device:
        port = open_serial(device.path, 115200, timeout=1.0, what="UM7")
        yield device, port
        port.close()


def answer(port, data_length):
    reply = port.read(7 + data_length)
    assert len(reply) == 7 + data_length
    assert int.from_bytes(reply[-2:], "big") == sum(reply[:-2])
    assert reply[:3] == b"snp"
    return reply[3], reply[4], reply[5:-2]


def test_the_simulator_answers_a_batch_read_of_the_euler_angles(sensor):
    device, port = sensor
    port.write(with_sum(SNP + [0x48, 0x70]))                 # batch read of 2 from 0x70
    packet_type, address, data = answer(port, 8)
    assert (packet_type, address) == (0xC8, 0x70)
    roll, pitch, yaw, unused = struct.unpack(">hhhh", data)
    assert (roll, pitch, yaw, unused) == (round(10 * 91.02222), round(-5 * 91.02222),
                                          round(30 * 91.02222), 0)


def test_the_simulator_answers_gravity_and_rates_as_floats(sensor):
    device, port = sensor
    port.write(with_sum(SNP + [0x00, 0x65]))                 # accel x alone
    packet_type, address, data = answer(port, 4)
    assert (packet_type, address) == (0x80, 0x65)
    assert struct.unpack(">f", data)[0] == pytest.approx(9.80665 * math.sin(math.radians(-5)),
                                                         rel=1e-6)


def test_writes_are_completed_and_commands_answered(sensor):
    device, port = sensor
    port.write(with_sum(SNP + [0x80, 0x03, 0, 0, 0, 0]))     # CREG_COM_RATES3 = 0
    assert answer(port, 0) == (0x00, 0x03, b"")
    port.write(with_sum(SNP + [0x00, 0xAA]))                 # GET_FW_REVISION
    assert answer(port, 4) == (0x80, 0xAA, FIRMWARE)
    port.write(with_sum(SNP + [0x00, 0xAD]))                 # ZERO_GYROS
    assert answer(port, 0) == (0x00, 0xAD, b"")


def test_broadcasts_follow_the_rate_registers(sensor):
    device, port = sensor
    port.write(with_sum(SNP + [0x80, 0x05, 0, 50, 0, 0]))    # Euler angles at 50 Hz
    assert answer(port, 0) == (0x00, 0x05, b"")
    packet_type, address, data = answer(port, 20)
    assert (packet_type, address) == (0xD4, 0x70)            # batch of 5 from 0x70


def test_the_driver_reads_answers_and_ignores_corrupt_packets():
    with VirtualUM7(roll=-20.0) as device:
        driver = um7.UM7(device.path)
        try:
            driver.request(um7.DREG_EULER_PHI_THETA)
            deadline = time.monotonic() + 2
            while driver.register(um7.DREG_EULER_PHI_THETA) is None:
                assert time.monotonic() < deadline
                time.sleep(0.005)
            assert um7.high_low(driver.register(0x70))[0] == round(-20 * 91.02222)
        finally:
            driver.close()
    with VirtualUM7(fault="corrupt") as device:
        driver = um7.UM7(device.path)
        try:
            driver.request(um7.DREG_EULER_PHI_THETA)
            deadline = time.monotonic() + 2
            while driver.parser.bad == 0:
                assert time.monotonic() < deadline
                time.sleep(0.005)
            assert driver.registers == {}
        finally:
            driver.close()
