"""Dynamixel packets, Protocol 1.0 and 2.0, at the byte level.

The drivers talk through ROBOTIS ``dynamixel-sdk``; this module is what the simulator uses to
read instruction packets and write status packets, and what the tests use to check bytes
against the packets published in the ROBOTIS e-manual.

Protocol 1.0: ``FF FF ID LEN INST PARAM... CHKSUM``, LEN = parameters + 2, CHKSUM = ~(ID +
LEN + INST + PARAMS) & 0xFF. Protocol 2.0: ``FF FF FD 00 ID LEN_L LEN_H INST PARAM... CRC_L
CRC_H``, LEN = parameters (after stuffing) + 3, CRC-16 (polynomial 0x8005, as in the e-manual)
over everything before it; ``FF FF FD`` inside the body is stuffed to ``FF FF FD FD``.
"""
from __future__ import annotations

from dataclasses import dataclass

BROADCAST_ID = 0xFE

# Instructions (both protocols unless marked).
PING, READ, WRITE, REG_WRITE, ACTION, FACTORY_RESET, REBOOT = 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x08
CLEAR = 0x10                                  # 2.0
STATUS = 0x55                                 # 2.0 status packets
SYNC_READ, SYNC_WRITE = 0x82, 0x83            # sync read: 2.0 only
BULK_READ, BULK_WRITE = 0x92, 0x93            # bulk read: 1.0 (MX) and 2.0; bulk write: 2.0

# Protocol 1.0 status error bits.
P1_INPUT_VOLTAGE, P1_ANGLE_LIMIT, P1_OVERHEATING, P1_RANGE = 0x01, 0x02, 0x04, 0x08
P1_CHECKSUM, P1_OVERLOAD, P1_INSTRUCTION = 0x10, 0x20, 0x40
P1_ERROR_NAMES = {P1_INPUT_VOLTAGE: "input voltage", P1_ANGLE_LIMIT: "angle limit",
                  P1_OVERHEATING: "overheating", P1_RANGE: "range", P1_CHECKSUM: "checksum",
                  P1_OVERLOAD: "overload", P1_INSTRUCTION: "instruction"}

# Protocol 2.0 status error field (bits 0-6 a number, bit 7 the hardware alert).
P2_RESULT_FAIL, P2_INSTRUCTION, P2_CRC, P2_DATA_RANGE, P2_DATA_LENGTH, P2_DATA_LIMIT, \
    P2_ACCESS = range(1, 8)
P2_ALERT = 0x80
P2_ERROR_NAMES = {P2_RESULT_FAIL: "result fail", P2_INSTRUCTION: "instruction error",
                  P2_CRC: "CRC error", P2_DATA_RANGE: "data range error",
                  P2_DATA_LENGTH: "data length error", P2_DATA_LIMIT: "data limit error",
                  P2_ACCESS: "access error"}
# Protocol 2.0 Hardware Error Status bits.
HW_INPUT_VOLTAGE, HW_OVERHEATING, HW_ENCODER, HW_ELECTRICAL_SHOCK, HW_OVERLOAD = 0x01, 0x04, 0x08, 0x10, 0x20


def _crc_table() -> list[int]:
    table = []
    for i in range(256):
        crc = i << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x8005) if crc & 0x8000 else crc << 1
        table.append(crc & 0xFFFF)
    return table


_CRC_TABLE = _crc_table()


def crc16(data: bytes) -> int:
    """The Protocol 2.0 CRC-16 (CRC-16/BUYPASS: polynomial 0x8005, initial 0, no reflection)."""
    crc = 0
    for byte in data:
        crc = ((crc << 8) ^ _CRC_TABLE[((crc >> 8) ^ byte) & 0xFF]) & 0xFFFF
    return crc


def checksum(body: bytes) -> int:
    """The Protocol 1.0 checksum of ID, LENGTH, INSTRUCTION/ERROR and parameters."""
    return ~sum(body) & 0xFF


def stuff(body: bytes) -> bytes:
    """Protocol 2.0 byte stuffing: FF FF FD becomes FF FF FD FD."""
    return bytes(body).replace(b"\xff\xff\xfd", b"\xff\xff\xfd\xfd")


def unstuff(body: bytes) -> bytes:
    return bytes(body).replace(b"\xff\xff\xfd\xfd", b"\xff\xff\xfd")


def packet1(ident: int, instruction_or_error: int, params: bytes = b"") -> bytes:
    """A Protocol 1.0 packet (instruction or status)."""
    body = bytes([ident, len(params) + 2, instruction_or_error]) + bytes(params)
    return b"\xff\xff" + body + bytes([checksum(body)])


def packet2(ident: int, instruction: int, params: bytes = b"") -> bytes:
    """A Protocol 2.0 packet; ``params`` are stuffed. A status packet is
    ``packet2(id, STATUS, bytes([error]) + data)``."""
    stuffed = stuff(bytes(params))
    length = len(stuffed) + 3
    head = bytes([0xFF, 0xFF, 0xFD, 0x00, ident, length & 0xFF, length >> 8, instruction]) + stuffed
    crc = crc16(head)
    return head + bytes([crc & 0xFF, crc >> 8])


@dataclass
class Packet:
    """A packet read from the bus."""
    protocol: int
    ident: int
    instruction: int        # or the error byte of a Protocol 1.0 status packet
    params: bytes
    valid: bool = True      # False when the checksum or CRC is wrong


class PacketReader:
    """Splits a byte stream into packets of one protocol version; skips noise before a header."""

    def __init__(self, protocol: int):
        self.protocol = protocol
        self.buffer = bytearray()

    def feed(self, data: bytes) -> list[Packet]:
        self.buffer += data
        packets = []
        while True:
            packet = self._next()
            if packet is None:
                return packets
            packets.append(packet)

    def _next(self) -> Packet | None:
        header = b"\xff\xff\xfd\x00" if self.protocol == 2 else b"\xff\xff"
        buf = self.buffer
        start = buf.find(header)
        if start < 0:
            keep = len(header) - 1          # a header may be split across reads
            del buf[:max(0, len(buf) - keep)]
            return None
        del buf[:start]
        if self.protocol == 1:
            if len(buf) >= 3 and buf[2] == 0xFF:     # FF FF FF ...: the first FF was noise
                del buf[:1]
                return self._next()
            if len(buf) < 4:
                return None
            length = buf[3]
            total = 4 + length
            if length < 2:
                del buf[:2]
                return self._next()
            if len(buf) < total:
                return None
            raw = bytes(buf[:total])
            del buf[:total]
            body = raw[2:-1]
            return Packet(1, raw[2], raw[4], raw[5:-1], checksum(body) == raw[-1])
        if len(buf) < 7:
            return None
        length = buf[5] | (buf[6] << 8)
        total = 7 + length
        if length < 3:
            del buf[:4]
            return self._next()
        if len(buf) < total:
            return None
        raw = bytes(buf[:total])
        del buf[:total]
        valid = crc16(raw[:-2]) == (raw[-2] | (raw[-1] << 8))
        return Packet(2, raw[4], raw[7], unstuff(raw[8:-2]), valid)


def writes_of(packet: Packet) -> list[tuple[int, int, bytes]]:
    """(id, address, data) of each value a Write, Sync Write or Bulk Write packet writes
    (e-Manual, "DYNAMIXEL Protocol 1.0" / "2.0": Write: address then data; Sync Write:
    address, length, then id and data per servo; Bulk Write (2.0): id, address, length and
    data per servo; addresses and lengths are one byte in 1.0, two in 2.0). Other
    instructions, and packets whose checksum or CRC is wrong, write nothing."""
    params, two = packet.params, packet.protocol == 2
    if not packet.valid:
        return []
    word = (lambda at: params[at] | (params[at + 1] << 8)) if two else (lambda at: params[at])
    step = 2 if two else 1
    if packet.instruction == WRITE and len(params) > step:
        return [(packet.ident, word(0), bytes(params[step:]))]
    out = []
    if packet.instruction == SYNC_WRITE and len(params) >= 2 * step:
        address, length, at = word(0), word(step), 2 * step
        while length and at + 1 + length <= len(params):
            out.append((params[at], address, bytes(params[at + 1:at + 1 + length])))
            at += 1 + length
    elif packet.instruction == BULK_WRITE and two:
        at = 0
        while at + 5 <= len(params):
            ident, address, length = params[at], word(at + 1), word(at + 3)
            out.append((ident, address, bytes(params[at + 5:at + 5 + length])))
            at += 5 + length
    return out
