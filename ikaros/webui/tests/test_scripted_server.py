"""A class written as a Python script in the real web UI server (127.0.0.1): the class
list and module info, parameters and commands from the HTTP API, the editor's Apply, and
Stop then Play, with one worker process per module throughout."""
from __future__ import annotations

import os
import time

import pytest

from browsing import Server

IKC = '''<class name="Acc" python="acc.py" description="adds gain times its input to its output">
    <parameter name="gain" type="number" default="1" description="the factor"/>
    <input name="INPUT"/>
    <output name="OUTPUT" size="INPUT.size"/>
</class>
'''

SCRIPT = '''def tick(module):
    module.OUTPUT[:] += module.INPUT * module.gain


def command(module, name, x, y, value):
    if name == "set":
        module.OUTPUT[:] = value
'''

MODEL = '''<group name="M" tick_duration="0.01">
    <module class="Constant" name="C" data="1 2"/>
    <module class="Acc" name="A"/>
    <connection source="C.OUTPUT" target="A.INPUT" delay="0"/>
</group>
'''


def _workers(server: Server) -> list[int]:
    """The worker processes the server has started (its children running worker.py)."""
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                command = f.read()
        except (FileNotFoundError, ProcessLookupError):
            continue
        if int(fields[1]) == server.proc.pid and fields[0] != "Z" and \
                b"scripted/worker.py" in command:
            found.append(int(pid))
    return found


def _settle(server: Server, count: int) -> list[int]:
    deadline = time.monotonic() + 10
    while len(found := _workers(server)) != count:
        assert time.monotonic() < deadline, f"{len(found)} workers, not {count}"
        time.sleep(0.05)
    return found


@pytest.fixture
def server(tmp_path):
    (tmp_path / "Acc.ikc").write_text(IKC)
    (tmp_path / "acc.py").write_text(SCRIPT)
    (tmp_path / "m.ikg").write_text(MODEL)
    srv = Server(str(tmp_path / "m.ikg"))
    yield srv
    srv.stop()


def test_a_scripted_class_in_the_web_ui(server, tmp_path):
    desc = server.get("/api/classes")["Acc"]
    assert desc["description"] == "adds gain times its input to its output"
    assert desc["script"] == str(tmp_path / "acc.py")
    assert desc["parameters"][0] == {"name": "gain", "type": "number", "default": "1",
                                     "description": "the factor"}
    info = server.get("/api/module?path=A")
    assert info["class"] == "Acc"
    assert [p["name"] for p in info["parameters"]][:2] == ["gain", "on_error"]
    (first,) = _settle(server, 1)

    server.step(2)
    assert server.data("A.OUTPUT")["data"]["A.OUTPUT"] == [2, 4]
    server.post("/api/parameter", {"path": "A.gain", "value": 10})
    server.step(1)
    assert server.data("A.OUTPUT")["data"]["A.OUTPUT"] == [12, 24]
    assert server.post("/api/command", {"module": "A", "name": "set", "value": [5, 6]}) == \
        {"ok": True}
    assert server.data("A.OUTPUT")["data"]["A.OUTPUT"] == [5, 6]

    tree = server.get("/api/model")["tree"]
    assert server.post("/api/apply", {"tree": tree})["ok"]
    (kept,) = _settle(server, 1)
    assert kept == first                # the module did not change: it goes on, worker too
    assert server.data("A.OUTPUT")["data"]["A.OUTPUT"] == [5, 6]     # outputs kept
    server.step(1)
    assert server.data("A.OUTPUT")["data"]["A.OUTPUT"] == [15, 26]
    (tmp_path / "acc.py").write_text(SCRIPT + "\n")        # the script changed: a new module
    assert server.post("/api/apply", {"tree": tree})["ok"]
    (second,) = _settle(server, 1)
    assert second != first                          # a new worker, the old one ended
    assert server.data("A.OUTPUT")["data"]["A.OUTPUT"] == [0, 0]     # started afresh

    server.post("/api/control", {"state": "stop"})
    _settle(server, 0)
    server.post("/api/control", {"state": "play"})
    deadline = time.monotonic() + 10
    while server.tick() < 3:
        assert time.monotonic() < deadline
        time.sleep(0.05)
    (third,) = _settle(server, 1)
    assert third not in (first, second)
    server.post("/api/control", {"state": "stop"})
    _settle(server, 0)
