"""Tests of the Logger module: it loads, runs and writes nothing."""
import os
import socket

from ikaros.testing import load_body as load


def test_does_nothing(tmp_path, capsys, monkeypatch):
    def no_network(*args, **kwargs):
        raise AssertionError("Logger must not use the network")

    monkeypatch.setattr(socket, "create_connection", no_network)
    monkeypatch.setattr(socket.socket, "connect", no_network)
    net = load(tmp_path, '<module class="Logger" name="Log"/>'
               '<module class="Constant" name="C" data="1"/>')
    try:
        before = sorted(os.listdir(tmp_path))
        net.run(ticks=3)
        assert net.tick == 3
        assert sorted(os.listdir(tmp_path)) == before          # no files
        assert [entry for entry in net.log if entry[2].endswith("Log")] == []
    finally:
        net.close()
    out = capsys.readouterr()
    assert out.out == "" and out.err == ""
