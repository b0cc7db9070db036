"""Dynamixel packets at the byte level, against packets published in the ROBOTIS e-manual."""
from __future__ import annotations

import pytest

from ikaros.hardware.dynamixel import protocol as p

H = bytes.fromhex


def test_protocol1_packets_of_the_e_manual():
    assert p.packet1(1, p.PING) == H("FF FF 01 02 01 FB")
    assert p.packet1(1, 0) == H("FF FF 01 02 00 FC")                         # its status
    assert p.packet1(1, p.READ, bytes([0x2B, 1])) == H("FF FF 01 04 02 2B 01 CC")   # read temperature
    assert p.packet1(1, 0, bytes([0x20])) == H("FF FF 01 03 00 20 DB")         # status: 32 degrees
    assert p.packet1(0xFE, p.WRITE, bytes([3, 1])) == H("FF FF FE 04 03 03 01 F6")  # set id 1
    sync = bytes([0x1E, 4, 0, 0x10, 0, 0x50, 1, 1, 0x20, 2, 0x60, 3, 2, 0x30, 0, 0x70, 1,
                  3, 0x20, 2, 0x80, 3])
    assert p.packet1(0xFE, p.SYNC_WRITE, sync) == H(
        "FF FF FE 18 83 1E 04 00 10 00 50 01 01 20 02 60 03 02 30 00 70 01 03 20 02 80 03 12")


def test_protocol2_packets_of_the_e_manual():
    assert p.packet2(1, p.PING) == H("FF FF FD 00 01 03 00 01 19 4E")
    assert p.packet2(1, p.STATUS, bytes([0, 0x06, 0x04, 0x26])) == H("FF FF FD 00 01 07 00 55 00 06 04 26 65 5D")
    assert p.packet2(1, p.READ, bytes([0x84, 0, 4, 0])) == H("FF FF FD 00 01 07 00 02 84 00 04 00 1D 15")
    assert p.packet2(1, p.STATUS, bytes([0, 0xA6, 0, 0, 0])) == H("FF FF FD 00 01 08 00 55 00 A6 00 00 00 8C C0")
    assert p.packet2(1, p.WRITE, bytes([0x74, 0, 0, 2, 0, 0])) == H("FF FF FD 00 01 09 00 03 74 00 00 02 00 00 CA 89")
    assert p.packet2(1, p.STATUS, bytes([0])) == H("FF FF FD 00 01 04 00 55 00 A1 0C")
    assert p.packet2(0xFE, p.SYNC_WRITE, bytes([0x74, 0, 4, 0, 1, 0x96, 0, 0, 0, 2, 0xAA, 0, 0, 0])) == H(
        "FF FF FD 00 FE 11 00 83 74 00 04 00 01 96 00 00 00 02 AA 00 00 00 82 87")
    assert p.packet2(0xFE, p.SYNC_READ, bytes([0x84, 0, 4, 0, 1, 2])) == H("FF FF FD 00 FE 09 00 82 84 00 04 00 01 02 CE FA")


def test_crc16_known_values_and_the_sdk_agree():
    from dynamixel_sdk import PacketHandler
    sdk = PacketHandler(2.0)
    assert p.crc16(b"123456789") == 0xFEE8                       # CRC-16/BUYPASS check value
    for data in (b"", H("FF FF FD 00 01 03 00 01"), bytes(range(200))):
        assert p.crc16(data) == sdk.updateCRC(0, list(data), len(data))


def test_byte_stuffing():
    assert p.stuff(H("01 FF FF FD 02")) == H("01 FF FF FD FD 02")
    assert p.unstuff(H("01 FF FF FD FD 02")) == H("01 FF FF FD 02")
    packet = p.packet2(1, p.WRITE, H("FF FF FD 07"))                     # length counts the stuffed byte
    assert packet[:8] == H("FF FF FD 00 01 08 00 03") and packet[8:13] == H("FF FF FD FD 07")
    reader = p.PacketReader(2)
    [read] = reader.feed(packet)
    assert (read.ident, read.instruction, read.params, read.valid) == (1, p.WRITE, H("FF FF FD 07"), True)


def test_reader_splits_streams_and_flags_bad_checksums():
    reader = p.PacketReader(1)
    stream = b"\x00\x13" + p.packet1(1, p.PING) + p.packet1(2, p.READ, bytes([0x24, 2]))
    assert reader.feed(stream[:5]) == []
    first, second = reader.feed(stream[5:])
    assert (first.ident, first.instruction, second.ident, second.params) == (1, p.PING, 2, bytes([0x24, 2]))
    broken = bytearray(p.packet1(1, p.PING))
    broken[-1] ^= 1
    [bad] = reader.feed(bytes(broken))
    assert not bad.valid
    reader2 = p.PacketReader(2)
    broken2 = bytearray(p.packet2(1, p.PING))
    broken2[-2] ^= 1
    [bad2] = reader2.feed(bytes(broken2))
    assert not bad2.valid


@pytest.mark.parametrize("model, raw, degrees", [("AX-12A", 512, 180.0), ("AX-12A", 0, 30.0),
                                                 ("MX-28", 2048, 180.0), ("XM430-W350", 0, 0.0),
                                                 ("XM430-W350", 3072, 270.0), ("XL-320", 1023, 329.70703125)])
def test_control_tables_convert_positions_to_degrees(model, raw, degrees):
    from ikaros.hardware.dynamixel.control_table import table_for_model
    role = table_for_model(model).role("PRESENT_POSITION")
    assert role.to_value(raw) == pytest.approx(degrees)
    assert role.to_raw(degrees) == raw


def test_control_tables_of_every_series():
    from ikaros.hardware.dynamixel.control_table import table_for_model, table_for_number
    ax = table_for_model("AX-12A")
    assert (ax.protocol, ax.model_number, ax.field("Goal Position").address, ax.field("Present Load").address) == (1, 12, 30, 40)
    xm = table_for_model("XM430-W350")
    assert (xm.protocol, xm.field("Goal Position").address, xm.field("Goal Position").size) == (2, 116, 4)
    assert xm.role("PRESENT_LOAD").field.name == "Present Current"
    assert table_for_model("XL430-W250").role("PRESENT_LOAD").field.name == "Present Load"
    assert table_for_model("XL430-W250").role("PRESENT_CURRENT") is None
    assert table_for_model("MX-64").field("Goal Torque").address == 71
    assert "Goal Torque" not in table_for_model("MX-28").fields
    assert table_for_model("XL-320").field("Present Position").address == 37
    assert table_for_model("XM540-W270").model_number == 1120
    assert table_for_number(311, 2).model == "MX-64(2.0)" and table_for_number(29, 1).model == "MX-28"
    assert table_for_number(29, 2) is None
    load = ax.role("PRESENT_LOAD")
    assert load.to_value(1024 + 512) == pytest.approx(-512 / 1023) and load.to_raw(-512 / 1023) == 1536
    speed = xm.role("PRESENT_SPEED")
    assert speed.to_raw(-0.5) == (1 << 32) - 249 and speed.to_value((1 << 32) - 249) == pytest.approx(-249 * 0.0020087719)


def test_every_model_of_every_table_has_the_roles_the_driver_needs():
    from ikaros.hardware.dynamixel.control_table import all_models, table_for_model
    needed = {"MODEL_NUMBER", "ID", "BAUD_RATE", "TORQUE_ENABLE", "LED", "GOAL_POSITION", "MOVING_SPEED",
              "TORQUE_LIMIT", "PRESENT_POSITION", "PRESENT_SPEED", "PRESENT_LOAD", "PRESENT_VOLTAGE",
              "PRESENT_TEMPERATURE", "MIN_POSITION", "MAX_POSITION", "TEMPERATURE_LIMIT", "MOVING"}
    assert len(all_models()) == 23
    for model in all_models():
        table = table_for_model(model)
        assert needed <= set(table.roles), model
        addresses = sorted((f.address, f.address + f.size) for f in table.fields.values())
        assert all(end <= start for (_, end), (start, _) in zip(addresses, addresses[1:])), model


def test_writes_of_write_sync_write_and_bulk_write_packets_of_the_e_manual():
    """The e-Manual's example packets: Protocol 1.0 Sync Write (ids 0..3, Goal Position and
    Moving Speed, 4 bytes at 0x1E); Protocol 2.0 Write (Goal Position 512 of id 1) and Sync
    Write (ids 1 and 2, 4 bytes at 116); and a Bulk Write laid out as its section gives (id,
    address, length, data per servo: id 1 LED at 65, id 2 Goal Position at 116)."""
    reader1 = p.PacketReader(1)
    [sync1] = reader1.feed(H("FF FF FE 18 83 1E 04 00 10 00 50 01 01 20 02 60 03 02 30 00 70 01 03 20 02 80 03 12"))
    assert p.writes_of(sync1) == [(0, 0x1E, H("10 00 50 01")), (1, 0x1E, H("20 02 60 03")),
                                  (2, 0x1E, H("30 00 70 01")), (3, 0x1E, H("20 02 80 03"))]
    reader2 = p.PacketReader(2)
    write, sync2, bulk = reader2.feed(
        H("FF FF FD 00 01 09 00 03 74 00 00 02 00 00 CA 89")
        + H("FF FF FD 00 FE 11 00 83 74 00 04 00 01 96 00 00 00 02 AA 00 00 00 82 87")
        + p.packet2(0xFE, p.BULK_WRITE, H("01 41 00 01 00 01 02 74 00 04 00 00 02 00 00")))
    assert p.writes_of(write) == [(1, 116, H("00 02 00 00"))]
    assert p.writes_of(sync2) == [(1, 116, H("96 00 00 00")), (2, 116, H("AA 00 00 00"))]
    assert p.writes_of(bulk) == [(1, 65, H("01")), (2, 116, H("00 02 00 00"))]
    assert p.writes_of(p.Packet(2, 1, p.READ, H("84 00 04 00"))) == []
