"""Tests of the OscInterface module: real OSC packets over UDP on 127.0.0.1 only."""

import socket
import struct
import time

import numpy as np
import pytest

from ikaros.module import EXCEPTION, WARNING
from ikaros.modules.utility.OscInterface import (decode_packet, encode_bundle,
                                                 encode_message)
from ikaros.testing import load_body as load

HOST = "127.0.0.1"


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind((HOST, 0))
        return s.getsockname()[1]


def osc_string(text):
    raw = text.encode()
    return raw + b"\0" * (4 - len(raw) % 4)


def message(address, tags, *payload):
    """An OSC message written out by hand: the payload is already packed."""
    return osc_string(address) + osc_string("," + tags) + b"".join(payload)


def f32(v):
    return struct.pack(">f", v)


def i32(v):
    return struct.pack(">i", v)


def bundle(*parts):
    return b"#bundle\0" + struct.pack(">Q", 1) + b"".join(i32(len(p)) + p for p in parts)


@pytest.fixture
def sender():
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    yield lambda packet, port: s.sendto(packet, (HOST, port))
    s.close()


def step_until(net, done, tries=100):
    """Step until done() holds (UDP delivery on the loopback is quick but not promised to
    be immediate)."""
    for _ in range(tries):
        net.step()
        if done():
            return True
        time.sleep(0.01)
    return False


def receiver_model(tmp_path, port, addresses="/a;/b/c:2", extra=""):
    return load(tmp_path, f'<module class="OscInterface" name="O" inhost="{HOST}" '
                          f'inport="{port}" inadresses="{addresses}" {extra}/>')


def test_outputs_follow_the_addresses(tmp_path):
    net = receiver_model(tmp_path, free_port(), "/a;/b/c:2;/d:3")
    try:
        assert net.output("O.OUTPUT_1").shape == (1,)
        assert net.output("O.OUTPUT_2").shape == (2,)
        assert net.output("O.OUTPUT_3").shape == (3,)
        net.step()                              # nothing received: the outputs stay 0
        assert np.all(net.output("O.OUTPUT_3") == 0)
    finally:
        net.close()


def test_receives_messages_and_bundles(tmp_path, sender):
    port = free_port()
    net = receiver_model(tmp_path, port)
    try:
        sender(message("/a", "f", f32(0.25)), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_1")[0] == 0.25)
        # ints are numbers too; a bundle delivers all its messages
        sender(bundle(message("/b/c", "if", i32(3), f32(-4.5)),
                      message("/a", "f", f32(7))), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_2")[1] == -4.5)
        assert np.array_equal(net.output("O.OUTPUT_2"), [3, -4.5])
        assert net.output("O.OUTPUT_1")[0] == 7
        # values are held until a new message arrives
        net.run(ticks=3)
        assert net.output("O.OUTPUT_1")[0] == 7
        # fewer arguments than values: the rest keep their values; True is 1
        sender(message("/b/c", "T"), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_2")[0] == 1)
        assert np.array_equal(net.output("O.OUTPUT_2"), [1, -4.5])
    finally:
        net.close()


def test_address_patterns_and_unhandled_messages(tmp_path, sender, capsys):
    port = free_port()
    net = receiver_model(tmp_path, port, "/x/one;/x/two;/y", 'show_unhandled="yes"')
    try:
        sender(message("/x/*", "f", f32(2)), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_2")[0] == 2)
        assert net.output("O.OUTPUT_1")[0] == 2 and net.output("O.OUTPUT_3")[0] == 0
        sender(message("/{y,z}", "f", f32(5)), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_3")[0] == 5)
        sender(message("/x/on?", "f", f32(6)), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_1")[0] == 6)
        assert net.output("O.OUTPUT_2")[0] == 2
        sender(message("/nobody", "f", f32(1)), port)
        sender(message("/y", "s", osc_string("text")), port)     # no number: unhandled
        sender(message("/y", "f", f32(9)), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_3")[0] == 9)
        printed = capsys.readouterr().out
        assert "/nobody" in printed and "text" in printed
    finally:
        net.close()


def test_malformed_packets_are_skipped_with_one_warning(tmp_path, sender):
    port = free_port()
    net = receiver_model(tmp_path, port)
    try:
        sender(b"garbage", port)
        sender(message("/a", "ff", f32(1)), port)                 # a missing argument
        sender(b"#bundle\0" + bytes(8) + i32(400) + bytes(8), port)
        sender(message("/a", "f", f32(1.5)), port)
        assert step_until(net, lambda: net.output("O.OUTPUT_1")[0] == 1.5)
        warnings = [e for e in net.log if e[1] == WARNING]
        assert len(warnings) == 1 and "malformed" in warnings[0][3]
    finally:
        net.close()


def test_sends_inputs_every_tick(tmp_path):
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as listener:
        listener.bind((HOST, 0))
        listener.settimeout(5)
        port = listener.getsockname()[1]
        net = load(tmp_path, '<module class="Sweep" name="S" outputsize="2" min="0" max="10" '
                             'step="1"/>'
                             '<module class="Constant" name="C" data="1.5 -2; 3 4"/>'
                             f'<module class="OscInterface" name="O" outhost="{HOST}" '
                             f'outport="{port}" outadresses="/sweep:2;/matrix;/unused"/>'
                             '<connection source="S.OUTPUT" target="O.INPUT_1" delay="0"/>'
                             '<connection source="C.OUTPUT" target="O.INPUT_2" delay="0"/>')
        try:
            for tick in range(3):
                net.step()
                packets = [listener.recv(1024) for _ in range(2)]
                assert packets[0] == message("/sweep", "ff", f32(tick + 1), f32(tick + 1))
                assert packets[1] == message("/matrix", "ffff", f32(1.5), f32(-2), f32(3),
                                             f32(4))
            # the unconnected INPUT_3 sends nothing, and INPUT_2 (4 values for an
            # address without a count) gives no warning
            listener.settimeout(0.05)
            with pytest.raises(socket.timeout):
                listener.recv(1024)
            assert not [e for e in net.log if e[1] == WARNING]
        finally:
            net.close()


def test_loopback_and_stop_closes_the_sockets(tmp_path):
    port = free_port()
    net = load(tmp_path, '<module class="Sweep" name="S" min="0" max="10" step="1"/>'
                         f'<module class="OscInterface" name="O" inhost="{HOST}" '
                         f'inport="{port}" outhost="{HOST}" outport="{port}" '
                         'inaddresses="/loop" outaddresses="/loop"/>'
                         '<connection source="S.OUTPUT" target="O.INPUT_1" delay="0"/>')
    try:
        assert step_until(net, lambda: net.output("O.OUTPUT_1")[0] == net.output("S.OUTPUT")[0])
    finally:
        net.close()
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind((HOST, port))                   # the module's socket is closed


def test_a_busy_port_is_an_error_and_the_run_goes_on(tmp_path):
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as busy:
        busy.bind((HOST, 0))
        port = busy.getsockname()[1]
        net = receiver_model(tmp_path, port)
        try:
            net.run(ticks=2)
            assert net.tick == 2
            errors = [e for e in net.log if e[1] == EXCEPTION]
            assert len(errors) == 1 and str(port) in errors[0][3]
            assert net.output("O.OUTPUT_1")[0] == 0
        finally:
            net.close()


def test_encoding_and_decoding_functions():
    packet = encode_message("/all", [1, 2.5, "hi", b"\x01\x02\x03", True, False, None])
    assert packet == (osc_string("/all") + osc_string(",ifsbTFN") + i32(1) + f32(2.5)
                      + osc_string("hi") + i32(3) + b"\x01\x02\x03\0")
    assert decode_packet(packet) == [("/all", "ifsbTFN",
                                      [1, 2.5, "hi", b"\x01\x02\x03", True, False, None])]
    nested = encode_bundle([encode_message("/a", [1.0]),
                            encode_bundle([encode_message("/b", [2])])])
    assert decode_packet(nested) == [("/a", "f", [1.0]), ("/b", "i", [2])]
    with pytest.raises(ValueError):
        decode_packet(b"abcd")
