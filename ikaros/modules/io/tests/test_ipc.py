"""Tests of IPCServer and IPCClient: kernels linked over loopback."""
import os
import signal
import socket
import subprocess
import sys
import time

import pytest

from ikaros.errors import ModelError
from ikaros.module import WARNING, EXCEPTION
from ikaros.testing import load_body as load, step_until

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def server_body(port, source='<module class="Sweep" name="S" min="0" max="1000" step="1"/>',
                attrs=""):
    return (f'{source}\n<module class="IPCServer" name="Server" port="{port}" {attrs}/>\n'
            '<connection source="S.OUTPUT" target="Server.INPUT" delay="0"/>')


def client_body(port, attrs=""):
    return f'<module class="IPCClient" name="Client" port="{port}" {attrs}/>'


def messages(net, level):
    return [m for _, lv, _, m in net.log if lv == level]


def test_two_kernels_give_the_values_of_one(tmp_path):
    port = free_port()
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    (tmp_path / "c").mkdir()
    one = load(tmp_path / "a", '<module class="Sweep" name="S" min="0" max="1000" step="1"/>')
    reference = []
    for _ in range(40):
        one.step()
        reference.append(one.output("S.OUTPUT").copy())
    one.close()
    server = load(tmp_path / "b", server_body(port))
    client = load(tmp_path / "c", client_body(port, 'shape="1" mode="each" '
                                                    'time_out_in_ms="2000"'))
    try:
        # messages published before the subscription is up are not delivered (ZeroMQ)
        step_until([server, client], lambda: client.output("Client.TICK")[0] >= 0)
        first = int(client.output("Client.TICK")[0])
        for _ in range(20):
            server.step()
            client.step()
            tick = int(client.output("Client.TICK")[0])
            assert client.output("Client.TIME_OUT")[0] == 0
            assert client.output("Client.OUTPUT").tolist() == reference[tick].tolist()
        assert tick == first + 20                # every tick of the server, in order
        assert 0 <= client.output("Client.LATENCY")[0] < 2
    finally:
        server.close()
        client.close()


def test_arrays_keep_their_shape_and_a_small_message_fills_the_start(tmp_path):
    port = free_port()
    (tmp_path / "s").mkdir()
    (tmp_path / "c").mkdir()
    server = load(tmp_path / "s", server_body(
        port, '<module class="Constant" name="S" data="1 2 3; 4 5 6"/>'))
    client = load(tmp_path / "c", client_body(port, 'shape="2, 3" time_out_in_ms="100"') +
                  client_body(port, 'shape="8" time_out_in_ms="100"').replace('"Client"',
                                                                              '"Wide"'))
    try:
        step_until([server, client], lambda: client.output("Client.TICK")[0] >= 0
                   and client.output("Wide.TICK")[0] >= 0)
        assert client.output("Client.OUTPUT").tolist() == [[1, 2, 3], [4, 5, 6]]
        assert client.output("Wide.OUTPUT").tolist() == [1, 2, 3, 4, 5, 6, 0, 0]
    finally:
        server.close()
        client.close()


def test_no_server_times_out_and_keeps_the_last_values(tmp_path):
    client = load(tmp_path, client_body(free_port(), 'time_out_in_ms="50"'))
    try:
        start = time.monotonic()
        client.run(ticks=3)
        assert time.monotonic() - start >= 0.15
        assert client.output("Client.TIME_OUT").tolist() == [1]
        assert client.output("Client.OUTPUT").tolist() == [0] * 20
        assert client.output("Client.TICK").tolist() == [-1]
    finally:
        client.close()


def _start_server(folder, port):
    return subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-r", "-q",
                             str(folder / "model.ikg")], cwd=ROOT,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def test_a_server_killed_and_restarted_mid_run(tmp_path):
    port = free_port()
    (tmp_path / "s").mkdir()
    (tmp_path / "c").mkdir()
    (tmp_path / "s" / "model.ikg").write_text(
        f'<group name="Test" tick_duration="0.01">\n{server_body(port)}\n</group>\n')
    client = load(tmp_path / "c", client_body(port, 'shape="1" time_out_in_ms="20"'))
    server = _start_server(tmp_path / "s", port)
    try:
        step_until([client], lambda: client.output("Client.TICK")[0] >= 0, 20)
        before = client.output("Client.TICK")[0]
        server.send_signal(signal.SIGKILL)
        server.wait(10)
        step_until([client], lambda: any("lost" in m for m in messages(client, WARNING)))
        ticks = client.tick
        client.run(ticks=5)
        assert client.output("Client.TIME_OUT").tolist() == [1]
        last = client.output("Client.OUTPUT").tolist()
        assert last == [client.output("Client.TICK")[0] + 1]      # Sweep: tick + 1
        server = _start_server(tmp_path / "s", port)
        step_until([client], lambda: client.output("Client.TIME_OUT")[0] == 0, 20)
        assert any("reconnected" in m for m in messages(client, WARNING))
        # the new server counts from its own tick 0 again
        assert client.output("Client.TICK")[0] < before + 1000
        assert client.output("Client.OUTPUT")[0] == client.output("Client.TICK")[0] + 1
        assert client.tick > ticks and not client.stopped
    finally:
        server.kill()
        server.wait(10)
        client.close()


@pytest.mark.parametrize("server_key, client_key", [("right", "wrong"), ("right", ""),
                                                    ("", "right")])
def test_a_wrong_key_is_refused(tmp_path, monkeypatch, server_key, client_key):
    monkeypatch.delenv("IKAROS_LINK_KEY", raising=False)
    port = free_port()
    (tmp_path / "s").mkdir()
    (tmp_path / "c").mkdir()
    server = load(tmp_path / "s", server_body(port, attrs=f'key="{server_key}"'))
    client = load(tmp_path / "c", client_body(port, f'key="{client_key}" '
                                                    f'time_out_in_ms="20"'))
    try:
        step_until([server, client], lambda: messages(client, EXCEPTION))
        assert "key" in messages(client, EXCEPTION)[0]
        client.run(ticks=3)
        server.step()
        assert client.output("Client.TIME_OUT").tolist() == [1]
        assert client.output("Client.TICK").tolist() == [-1]
        assert len(messages(client, EXCEPTION)) == 1          # reported once
    finally:
        server.close()
        client.close()


def test_the_right_key_is_accepted(tmp_path, monkeypatch):
    monkeypatch.setenv("IKAROS_LINK_KEY", "shared secret")
    port = free_port()
    (tmp_path / "s").mkdir()
    (tmp_path / "c").mkdir()
    server = load(tmp_path / "s", server_body(port))
    client = load(tmp_path / "c", client_body(port, 'time_out_in_ms="20"'))
    try:
        step_until([server, client], lambda: client.output("Client.TICK")[0] >= 0)
        assert client.output("Client.OUTPUT")[0] == client.output("Client.TICK")[0] + 1
    finally:
        server.close()
        client.close()


def test_another_machine_needs_a_key(tmp_path, monkeypatch):
    monkeypatch.delenv("IKAROS_LINK_KEY", raising=False)
    with pytest.raises(ModelError, match="needs a shared key"):
        load(tmp_path, server_body(free_port(), attrs='bind="*"'))
    with pytest.raises(ModelError, match="needs a shared key"):
        load(tmp_path, client_body(9100, 'host="192.0.2.1"'))


def test_bad_shape_is_a_load_error(tmp_path):
    with pytest.raises(ModelError, match='shape="2, x"'):
        load(tmp_path, client_body(9100, 'shape="2, x"'))


def test_a_model_loaded_again_at_once_binds_the_port_its_last_run_let_go(tmp_path):
    """ZeroMQ releases a closed socket's port a moment later: loading the model again right
    after closing it (a reload, the next of several runs) waits for the port."""
    port = free_port()
    for _ in range(5):
        with load(tmp_path, server_body(port)) as net:
            net.step()
