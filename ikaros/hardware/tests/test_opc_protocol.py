"""Open Pixel Control messages at the byte level, and the client against the simulated server."""
from __future__ import annotations

import time

import numpy as np
import pytest

from ikaros.hardware import DeviceError
from ikaros.hardware.opc import (OPCClient, message, parse_messages, pixel_message,
                                 split_address)
from ikaros.hardware.opc_sim import VirtualOPCServer
from ikaros.testing import wait_for


def test_message_header_and_pixel_payload():
    assert message(1, 0, b"\x01\x02\x03") == b"\x01\x00\x00\x03\x01\x02\x03"
    assert message(0, 255, b"\x00\x01" + b"x" * 300)[:4] == b"\x00\xff\x01\x2e"  # 302 bytes
    # two pixels: (1, 0.5, 0) and (0.2, 1.5 -> 1, -1 -> 0); 0.5 * 255 = 127.5 rounds to 128
    assert pixel_message(7, [[1, 0.5, 0], [0.2, 1.5, -1]]) == \
        bytes([7, 0, 0, 6, 255, 128, 0, 51, 255, 0])
    with pytest.raises(ValueError, match="channel 256"):
        message(256, 0, b"")
    with pytest.raises(ValueError, match="do not fit"):
        message(0, 0, bytes(65536))


def test_parse_messages_keeps_incomplete_ones():
    buffer = bytearray(message(1, 0, b"abc") + message(2, 0, b"defg")[:5])
    assert parse_messages(buffer) == [(1, 0, b"abc")]
    assert buffer == message(2, 0, b"defg")[:5]
    buffer += b"efg"
    assert parse_messages(buffer) == [(2, 0, b"defg")] and buffer == b""


def test_addresses():
    assert split_address("127.0.0.1:7891") == ("127.0.0.1", 7891)
    assert split_address("localhost") == ("localhost", 7890)
    with pytest.raises(DeviceError, match="host:port"):
        split_address("host:abc")


def test_pixels_reach_the_server():
    with VirtualOPCServer() as server:
        client = OPCClient(server.path)
        try:
            client.set_pixels(3, np.array([[1, 0, 0], [0, 1, 0], [0, 0, 0.5]]))
            assert wait_for(lambda: 3 in server.pixels)
            assert server.pixels_of(3).tolist() == [[255, 0, 0], [0, 255, 0], [0, 0, 128]]
            assert server.messages == [(3, 0, bytes([255, 0, 0, 0, 255, 0, 0, 0, 128]))]
        finally:
            client.close()


def test_a_server_that_goes_away_is_reported():
    server = VirtualOPCServer().start()
    client = OPCClient(server.path)
    try:
        server.disconnect()
        with pytest.raises(DeviceError, match=f"OPC server at {server.path} is lost"):
            for _ in range(50):                  # the first writes may still be buffered
                client.set_pixels(0, np.zeros((10, 3)))
                time.sleep(0.01)
    finally:
        client.close()


def test_no_server_is_reported_with_its_address():
    with VirtualOPCServer() as server:
        address = server.path
    with pytest.raises(DeviceError, match=f"cannot connect to the OPC server at {address}"):
        OPCClient(address)


def test_a_server_that_hangs_is_reported():
    with VirtualOPCServer() as server:
        client = OPCClient(server.path, timeout=0.3)
        try:
            server.stall()
            big = np.zeros((21845, 3))                  # 65535 bytes a message
            with pytest.raises(DeviceError, match=f"OPC server at {server.path} does not "
                               "take data"):
                for _ in range(2000):                   # until the socket buffers are full
                    client.set_pixels(1, big)
        finally:
            client.close()
