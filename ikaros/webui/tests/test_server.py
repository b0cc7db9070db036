"""The web UI server: every endpoint, the token, bad requests, static files, the WebSocket
with its binary frames and flow control, and the real ``ikaros`` server process."""
from __future__ import annotations

import io
import json
import os
import signal
import socket
import subprocess
import sys
import time
import urllib.request
import warnings

import numpy as np
import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.encoding import decode_frame, encode_frame  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from ikaros.webui.snapshot import Snapshotter  # noqa: E402
from ikaros.webui.views import widget_class  # noqa: E402
from starlette.testclient import TestClient, WebSocketDenialResponse  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
DEMO = os.path.join(ROOT, "examples", "demo.ikg")

MODEL = """<?xml version="1.0"?>
<group name="T" dialect="2">
    <module class="Constant" name="C" data="1 2 3; 4 5 6" />
    <module class="Constant" name="Img" data="0 0.5; 1 0.25" />
    <module class="Constant" name="Rgb" data="[[[1, 0], [0, 1]], [[0, 1], [0, 1]], [[0, 0], [1, 1]]]" />
    <module class="Scale" name="S" factor="2" />
    <connection source="C.OUTPUT" target="S.INPUT" delay="0" />
    <module class="Randomizer" name="N" outputsize="8" interval="1" seed="1" />
    <module class="Histogram" name="H" size="4" elements="all" />
    <connection source="N.OUTPUT" target="H.INPUT" delay="0" />
    <module class="Gate" name="G" open="yes" />
    <connection source="N.OUTPUT" target="G.INPUT" delay="0" />
    <module class="FunctionGenerator" name="F" type="sin" />
    <view name="Main">
        <bar-graph x="10" y="20" width="100" height="50" source="S.OUTPUT" max="12" />
        <object class="SliderHorizontal" x="5" parameter="S.factor" />
        <button command="H.reset" label="Reset" />
        <image file="pic.png" />
    </view>
    <group name="Sub">
        <module class="Constant" name="K" data="7 8" />
        <output name="OUT" source="K.OUTPUT" />
        <widget class="BarGraph" _x="30" _y="40" source="K.OUTPUT" />
    </group>
    <group name="Plain">
        <module class="Constant" name="A" data="1" />
        <module class="Constant" name="B" data="2" />
    </group>
    <view name="Ports">
        <table source="Sub.OUT" />
    </view>
</group>
"""


@pytest.fixture
def net(tmp_path):
    path = tmp_path / "t.ikg"
    path.write_text(MODEL)
    (tmp_path / "pic.png").write_bytes(_png())
    (tmp_path / "secret.txt").write_text("secret")
    n = ikaros.load(str(path))
    n.log_level = WARNING
    yield n
    n.controller.stop()
    n.controller.join(5)
    n.close()


@pytest.fixture
def static(tmp_path):
    d = tmp_path / "static"
    d.mkdir()
    (d / "index.html").write_text("<!doctype html><title>ikaros</title>")
    (d / "app.js").write_text("export const x = 1;")
    return str(d)


@pytest.fixture
def client(net, static):
    with TestClient(create_app(net, static_dir=static)) as c:
        yield c


def _png() -> bytes:
    from PIL import Image
    out = io.BytesIO()
    Image.new("L", (2, 2), 128).save(out, "PNG")
    return out.getvalue()


def _error(r, status):
    assert r.status_code == status, (r.status_code, r.text)
    body = r.json()
    assert set(body) == {"error"} and body["error"]
    return body["error"]


def _wait(predicate, timeout=10.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.01)
    return False


# --- HTTP endpoints ----------------------------------------------------------------------

def test_status(client, net):
    s = client.get("/api/status").json()
    for key in ("state", "tick", "tick_duration", "time", "elapsed", "ticks_per_second",
                "actual_tick_duration", "lag", "lag_max", "lag_p99", "resyncs", "cpu_usage",
                "idle", "file"):
        assert key in s
    assert s["state"] == "pause" and s["tick"] == 0 and s["file"] == "t.ikg"


def test_network_with_views_from_both_forms_and_a_default_view(client):
    net = client.get("/api/network").json()
    assert net["file"] == "t.ikg" and net["name"] == "T"
    top = net["top"]
    assert [m["name"] for m in top["modules"]] == ["C", "Img", "Rgb", "S", "N", "H", "G", "F"]
    s = next(m for m in top["modules"] if m["name"] == "S")
    assert s["class"] == "Scale" and s["path"] == "S"
    assert s["outputs"] == [{"name": "OUTPUT", "shape": [2, 3]}]
    assert {"name": "INPUT", "shape": [2, 3]} in s["inputs"]
    assert s["parameters"] == [{"name": "factor", "type": "number", "value": 2.0,
                                "options": []}]
    assert {"source": "C.OUTPUT", "target": "S.INPUT", "delay": "0"} in top["connections"]
    main, ports = top["views"]
    assert main["name"] == "Main"
    bar, slider, button, image = main["widgets"]
    assert bar == {"class": "bar-graph", "x": 10, "y": 20, "width": 100, "height": 50,
                   "source": "S.OUTPUT", "max": "12", "source_path": "S.OUTPUT"}
    assert slider["class"] == "slider-horizontal" and slider["x"] == 5
    assert slider["parameter_path"] == "S.factor"
    assert button["command_module"] == "H" and button["command_name"] == "reset"
    assert image["file_url"] == "/files/pic.png"
    assert ports["widgets"][0]["source_path"] == "Sub.K.OUTPUT"     # through the alias
    sub = top["groups"][0]
    assert sub["path"] == "Sub" and sub["outputs"] == [{"name": "OUT", "source": "K.OUTPUT"}]
    (w,) = sub["views"][0]["widgets"]
    assert (w["class"], w["x"], w["y"], w["source_path"]) == ("bar-graph", 30, 40,
                                                              "Sub.K.OUTPUT")
    plain = top["groups"][1]["views"]
    assert len(plain) == 1 and plain[0]["default"]
    assert [(p["class"], p["x"], p["y"], p["width"], p["source_path"])
            for p in plain[0]["widgets"]] == [("plot", 20, 20, 200, "Plain.A.OUTPUT"),
                                              ("plot", 240, 20, 200, "Plain.B.OUTPUT")]


def test_widget_class_names():
    assert widget_class("BarGraph") == "bar-graph"
    assert widget_class("bar_graph") == "bar-graph"
    assert widget_class("SliderVertical") == "slider-vertical"
    assert widget_class("Canvas3D") == "canvas3d"
    assert widget_class("DropDownMenu") == "drop-down-menu"
    assert widget_class("MyOwnWidget") == "my-own-widget"


def test_classes_and_openapi(client):
    classes = client.get("/api/classes").json()
    assert classes["Scale"]["name"] == "Scale"
    assert any(p["name"] == "factor" for p in classes["Scale"]["parameters"])
    spec = client.get("/api/openapi.json").json()
    assert spec["openapi"].startswith("3.")
    for path in ("/api/network", "/api/classes", "/api/status", "/api/control",
                 "/api/parameter", "/api/command", "/api/module", "/api/data", "/api/log"):
        assert path in spec["paths"]


def test_module(client):
    m = client.get("/api/module", params={"path": "S"}).json()
    assert m["path"] == "S" and m["class"] == "Scale" and m["description"]
    (p,) = m["parameters"]
    assert (p["name"], p["type"], p["value"], p["default"]) == ("factor", "number", 2.0, 1.0)
    assert {i["name"]: i["connected"] for i in m["inputs"]} == {"INPUT": True, "SCALE": False}
    assert m["outputs"][0]["shape"] == [2, 3] and m["view"] is None
    _error(client.get("/api/module", params={"path": "Nope"}), 404)
    _error(client.get("/api/module", params={"path": "Sub"}), 404)
    _error(client.get("/api/module"), 400)
    _error(client.get("/api/module", params={"path": "S", "extra": "1"}), 400)


def test_data(client, net):
    r = client.get("/api/data", params={"paths": "C.OUTPUT,Sub.K.OUTPUT"}).json()
    assert r == {"tick": 0, "data": {"C.OUTPUT": [[1, 2, 3], [4, 5, 6]],
                                     "Sub.K.OUTPUT": [7, 8]}}
    _error(client.get("/api/data", params={"paths": "C.OUTPUT,C.NOPE"}), 404)
    _error(client.get("/api/data"), 400)
    _error(client.get("/api/data", params={"path": "C.OUTPUT"}), 400)


def test_log(client, net):
    first = client.get("/api/log").json()
    net.notify(WARNING, "S", "hello")
    net.notify(WARNING, None, "again")
    r = client.get("/api/log", params={"since": first["next"]}).json()
    assert [(m["level"], m["module"], m["message"]) for m in r["messages"]] == [
        ("warning", "S", "hello"), ("warning", "", "again")]
    assert r["next"] == r["messages"][-1]["seq"] + 1
    assert client.get("/api/log", params={"since": r["next"]}).json()["messages"] == []
    _error(client.get("/api/log", params={"since": "-1"}), 400)
    _error(client.get("/api/log", params={"since": "x"}), 400)


def test_control_runs_steps_and_pauses(client, net):
    r = client.post("/api/control", json={"state": "step"})
    assert r.status_code == 200 and "tick" in r.json()
    assert _wait(lambda: net.tick == 1 and net.controller.state == "pause")
    time.sleep(0.1)
    assert net.tick == 1
    client.post("/api/control", json={"state": "play"})
    assert _wait(lambda: net.tick > 10)
    assert client.post("/api/control", json={"state": "pause"}).json()["state"] == "pause"
    time.sleep(0.1)
    t = net.tick
    time.sleep(0.1)
    assert net.tick == t
    assert client.post("/api/control", json={"state": "realtime"}).json()["state"] == \
        "realtime"
    client.post("/api/control", json={"state": "pause"})
    assert client.post("/api/control", json={"state": "stop"}).json()["state"] == "stop"
    assert net.stopped and not net.controller.running              # the run has ended
    client.post("/api/control", json={"state": "step"})            # and runs again from 0
    again = client.app.state.ui.net
    assert again is not net and _wait(lambda: again.tick == 1)


def test_control_bad_requests(client, net):
    _error(client.post("/api/control", json={"state": "fly"}), 400)
    _error(client.post("/api/control", json={"state": 3}), 400)
    _error(client.post("/api/control", json={}), 400)
    _error(client.post("/api/control", json={"state": "play", "speed": 2}), 400)
    _error(client.post("/api/control", json=["play"]), 400)
    _error(client.post("/api/control", content=b"{not json",
                       headers={"content-type": "application/json"}), 400)
    _error(client.post("/api/control", content=b'{"state": "play"}',
                       headers={"content-type": "text/plain"}), 415)
    _error(client.get("/api/control"), 405)
    _error(client.post("/api/control?x=1", json={"state": "play"}), 400)
    assert net.controller.state == "pause" and net.tick == 0


def test_set_parameter(client, net):
    r = client.post("/api/parameter", json={"path": "S.factor", "value": 3})
    assert r.json() == {"path": "S.factor", "value": 3.0}
    assert net.parameter("S.factor") == 3.0
    assert client.post("/api/parameter", json={"path": "S.factor", "value": "0.5"}).json()[
        "value"] == 0.5
    r = client.post("/api/parameter", json={"path": "C.data", "value": 9, "x": 2, "y": 1})
    assert r.json()["value"] == [[1, 2, 3], [4, 5, 9]]
    assert client.post("/api/parameter", json={"path": "G.open", "value": False}).json()[
        "value"] is False
    assert client.post("/api/parameter", json={"path": "F.type", "value": "square"}).json()[
        "value"] == "square"
    assert client.post("/api/parameter", json={"path": "F.type", "value": 1}).json()[
        "value"] == "triangle"
    net.step()
    assert net.output("S.OUTPUT").tolist() == [[0.5, 1, 1.5], [2, 2.5, 4.5]]


@pytest.mark.parametrize("body,status", [
    ({"path": "S.nope", "value": 1}, 404),
    ({"path": "Nope.factor", "value": 1}, 404),
    ({"path": "Sub", "value": 1}, 404),
    ({"path": "S.factor"}, 400),
    ({"value": 1}, 400),
    ({"path": 5, "value": 1}, 400),
    ({"path": "S.factor", "value": 1, "extra": 1}, 400),
    ({"path": "S.factor", "value": None}, 400),
    ({"path": "S.factor", "value": True}, 422),
    ({"path": "S.factor", "value": [1, 2]}, 422),
    ({"path": "S.factor", "value": "abc"}, 422),
    ({"path": "S.factor", "value": {"a": 1}}, 400),
    ({"path": "G.open", "value": "maybe"}, 422),
    ({"path": "G.open", "value": 2}, 422),
    ({"path": "F.type", "value": "cosine"}, 422),
    ({"path": "F.type", "value": 9}, 422),
    ({"path": "N.outputsize", "value": 1.5}, 422),
    ({"path": "C.data", "value": 1, "x": 3, "y": 0}, 422),
    ({"path": "C.data", "value": 1, "x": 0, "y": 2}, 422),
    ({"path": "C.data", "value": 1, "x": -1}, 400),
    ({"path": "C.data", "value": 1, "x": 1.5}, 400),
    ({"path": "C.data", "value": "a", "x": 0}, 422),
    ({"path": "C.data", "value": [[1, "a"]]}, 400),
    ({"path": "S.factor", "value": 1, "x": 0}, 422),
])
def test_bad_parameter_requests_change_nothing(client, net, body, status):
    before = {p: net.parameter(p) for p in ("S.factor", "G.open", "F.type", "C.data",
                                             "N.outputsize")}
    _error(client.post("/api/parameter", json=body), status)
    for p, v in before.items():
        assert np.array_equal(net.parameter(p), v), p


def test_command(client, net):
    net.run(ticks=3)
    assert net.output("H.OUTPUT").sum() == 24
    assert client.post("/api/command", json={"module": "H", "name": "reset"}).json() == \
        {"ok": True}
    assert net.output("H.OUTPUT").tolist() == [0, 0, 0, 0]
    assert client.post("/api/command", json={"module": "H", "name": "reset", "x": 1,
                                             "y": 2, "value": "v"}).status_code == 200
    _error(client.post("/api/command", json={"module": "Nope", "name": "reset"}), 404)
    _error(client.post("/api/command", json={"module": "S", "name": "reset"}), 422)
    _error(client.post("/api/command", json={"module": "H"}), 400)
    _error(client.post("/api/command", json={"module": "H", "name": ""}), 400)
    _error(client.post("/api/command", json={"module": "H", "name": "reset", "x": "a"}),
           400)
    _error(client.post("/api/command", json={"module": "H", "name": "reset", "z": 0}), 400)


def test_unknown_paths_are_json_404(client):
    for path in ("/nope", "/api/nope", "/api", "/static/nope.js", "/files/nope.png"):
        _error(client.get(path), 404)


# --- static files ------------------------------------------------------------------------

def test_index_and_static_files(client):
    r = client.get("/")
    assert r.status_code == 200 and "<title>ikaros</title>" in r.text
    r = client.get("/static/app.js")
    assert r.status_code == 200 and "export" in r.text
    r = client.get("/files/pic.png")
    assert r.status_code == 200 and r.content == _png()


@pytest.mark.parametrize("path", [
    "/static/../server.py", "/static/..%2fserver.py", "/static/%2e%2e/server.py",
    "/static/%2e%2e%2fserver.py", "/static/..%2f..%2fsecret.txt", "/static/%2e%2e/secret.txt",
    "/static/..%5csecret.txt", "/static/%252e%252e/secret.txt", "/static//etc/passwd",
    "/static/%2fetc%2fpasswd", "/files/../t.ikg", "/files/%2e%2e/static/app.js",
    "/files/secret.txt", "/files/t.ikg", "/files/..%2f..%2fetc%2fpasswd",
    "/static/index.html%00.png",
])
def test_static_files_never_leave_their_folder(client, path):
    _error(client.get(path), 404)


# --- the token ---------------------------------------------------------------------------

def test_token_on_http(net, static):
    with TestClient(create_app(net, token="s3cret", static_dir=static)) as c:
        _error(c.get("/api/status"), 401)
        _error(c.get("/"), 401)
        _error(c.get("/static/app.js"), 401)
        _error(c.get("/api/status", headers={"Authorization": "Bearer wrong"}), 401)
        _error(c.get("/api/status", params={"token": "wrong"}), 401)
        _error(c.post("/api/control", json={"state": "play"}), 401)
        assert net.controller.state == "pause"
        assert c.get("/api/status", headers={"Authorization": "Bearer s3cret"}).status_code \
            == 200
        r = c.get("/", params={"token": "s3cret"})
        assert r.status_code == 200 and "ikaros_token=s3cret" in r.headers["set-cookie"]
        # the cookie set by the query token lets the app load its files
        assert c.get("/static/app.js").status_code == 200
        c.cookies.clear()
        _error(c.get("/static/app.js"), 401)
        assert c.get("/api/module", params={"path": "S", "token": "s3cret"}).status_code \
            == 200


def test_token_on_the_websocket(net):
    with TestClient(create_app(net, token="s3cret")) as c:
        with pytest.raises(WebSocketDenialResponse) as denied:
            with c.websocket_connect("/api/ws"):
                pass
        assert denied.value.status_code == 401
        with pytest.raises(WebSocketDenialResponse):
            with c.websocket_connect("/api/ws?token=nope"):
                pass
        with c.websocket_connect("/api/ws?token=s3cret") as ws:
            assert ws.receive_json()["type"] == "status"
        with c.websocket_connect("/api/ws", headers={"Authorization": "Bearer s3cret"}) as ws:
            assert ws.receive_json()["type"] == "status"


def test_cross_origin_changes_are_refused(client, net):
    _error(client.post("/api/control", json={"state": "play"},
                       headers={"Origin": "http://evil.example"}), 403)
    assert net.controller.state == "pause"
    with pytest.raises(WebSocketDenialResponse):
        with client.websocket_connect("/api/ws", headers={"Origin": "http://evil.example"}):
            pass
    assert client.post("/api/control", json={"state": "pause"},
                       headers={"Origin": "http://testserver"}).status_code == 200


def test_other_host_names_are_refused_when_asked(net):
    with TestClient(create_app(net, hosts=("127.0.0.1", "localhost")),
                    base_url="http://127.0.0.1:8000") as c:
        assert c.get("/api/status").status_code == 200
        assert c.get("/api/status", headers={"Host": "localhost:8000"}).status_code == 200
        _error(c.get("/api/status", headers={"Host": "evil.example:8000"}), 400)


# --- the WebSocket -----------------------------------------------------------------------

def _frame(ws):
    """The next binary frame, skipping text messages."""
    while True:
        m = ws.receive()
        if m.get("bytes") is not None:
            return decode_frame(m["bytes"])


def _text(ws, kind):
    while True:
        m = ws.receive()
        if m.get("text") is not None:
            msg = json.loads(m["text"])
            if msg["type"] == kind:
                return msg


def test_websocket_subscribe_ready_and_exact_frames(client, net):
    with client.websocket_connect("/api/ws") as ws:
        assert ws.receive_json()["type"] == "status"
        ws.send_json({"type": "ping", "t": 12.5})
        assert _text(ws, "pong") == {"type": "pong", "t": 12.5}
        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "S.OUTPUT", "format": "raw"}, {"path": "Sub.K.OUTPUT"},
            {"path": "C.OUTPUT"}]})
        ws.send_json({"type": "ready"})
        header, data = _frame(ws)
        assert header["tick"] == 0
        assert [(b["path"], b["format"], b["shape"]) for b in header["buffers"]] == [
            ("S.OUTPUT", "raw", [2, 3]), ("Sub.K.OUTPUT", "raw", [2]),
            ("C.OUTPUT", "raw", [2, 3])]
        assert [(b["offset"], b["length"]) for b in header["buffers"]] == [
            (0, 24), (24, 8), (32, 24)]
        assert data["S.OUTPUT"].tolist() == [[0, 0, 0], [0, 0, 0]]     # S has not ticked
        assert data["C.OUTPUT"].tolist() == [[1, 2, 3], [4, 5, 6]]     # written in init
        assert data["Sub.K.OUTPUT"].tolist() == [7, 8]
        client.post("/api/parameter", json={"path": "S.factor", "value": -1})
        client.post("/api/control", json={"state": "step"})
        assert _wait(lambda: net.tick == 1)
        ws.send_json({"type": "ready"})
        header, data = _frame(ws)
        assert header["tick"] == 1 and header["time"] == 0.0     # the time of tick 0
        assert data["S.OUTPUT"].tolist() == [[-1, -2, -3], [-4, -5, -6]]


def test_websocket_images(client):
    from PIL import Image
    with client.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "Img.OUTPUT", "format": "png"}, {"path": "Rgb.OUTPUT", "format": "png"},
            {"path": "C.OUTPUT", "format": "jpeg"}]})
        ws.send_json({"type": "ready"})
        header, data = _frame(ws)
        assert [b["format"] for b in header["buffers"]] == ["png", "png", "jpeg"]
        body = [data[b["path"]] for b in header["buffers"]]
        gray = np.asarray(Image.open(io.BytesIO(body[0])))
        assert gray.tolist() == [[0, 128], [255, 64]]
        rgb = np.asarray(Image.open(io.BytesIO(body[1])))
        assert rgb.shape == (2, 2, 3) and rgb[:, :, 0].tolist() == [[255, 0], [0, 255]]
        assert rgb[:, :, 2].tolist() == [[0, 0], [255, 255]]
        jpeg = Image.open(io.BytesIO(body[2]))
        assert jpeg.format == "JPEG" and jpeg.size == (3, 2)


def test_websocket_bad_messages_get_errors_and_change_nothing(client, net):
    with client.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [{"path": "S.OUTPUT"}]})
        for bad in ({"type": "fly"}, {"no": "type"}, [1],
                    {"type": "subscribe", "buffers": [{"path": "S.NOPE"}]},
                    {"type": "subscribe", "buffers": [{"path": "S.OUTPUT", "format": "gif"}]},
                    {"type": "subscribe", "buffers": [{"path": "C.OUTPUT", "format": "png",
                                                       "x": 1}]},
                    {"type": "subscribe", "buffers": [{"path": "N.OUTPUT",
                                                       "format": "png"}]},
                    {"type": "subscribe", "buffers": "S.OUTPUT"}):
            ws.send_json(bad)
            assert _text(ws, "error")["error"]
        ws.send_text("{not json")
        assert _text(ws, "error")["error"]
        ws.send_bytes(b"\x00")
        assert _text(ws, "error")["error"]
        ws.send_json({"type": "ready"})            # the first subscription still holds
        header, data = _frame(ws)
        assert list(data) == ["S.OUTPUT"]


def test_flow_control_one_frame_per_ready(client, net):
    ui = client.app.state.ui
    with client.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [{"path": "N.OUTPUT"}]})
        client.post("/api/control", json={"state": "play"})
        ticks = []
        for _ in range(3):
            ws.send_json({"type": "ready"})
            header, _ = _frame(ws)
            ticks.append(header["tick"])
        assert ticks == sorted(ticks) and len(set(ticks)) == 3
        (c,) = ui.hub.clients
        time.sleep(0.3)
        assert c.frames_sent == 3 and not c.ready      # nothing more without "ready"
        client.post("/api/control", json={"state": "pause"})


def test_a_stalled_client_does_not_block_ticks(client, net):
    ui = client.app.state.ui
    paths = [f"{m}.OUTPUT" for m in ("C", "Img", "Rgb", "S", "N", "H", "G", "F")]
    with client.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [{"path": p} for p in paths]})
        ws.send_json({"type": "ready"})
        _frame(ws)                      # one frame, then never "ready" again
        copies = ui.hub.snap.copies
        client.post("/api/control", json={"state": "play"})
        t0 = net.tick
        time.sleep(0.5)
        assert net.tick - t0 > 100
        assert ui.hub.snap.copies == copies      # nothing is copied for a stalled client
        client.post("/api/control", json={"state": "pause"})
        ws.send_json({"type": "ready"})          # it comes back: the newest data
        header, _ = _frame(ws)
        assert header["tick"] == net.tick


def test_snapshot_budget_spreads_copies_over_ticks(net):
    snap = Snapshotter(net, budget=0.0)
    snap.set_sources({p: net.buffer_array(p) for p in ("C.OUTPUT", "S.OUTPUT", "Sub.K.OUTPUT")})
    got = []
    snap.hook()                                   # nothing requested: nothing done
    snap.request(got.append)
    snap.hook()
    snap.hook()
    assert got == [] and snap.pending             # one buffer per tick with no budget
    snap.hook()
    (s,) = got
    assert not snap.pending and s.tick == 0
    assert s.plan.arrays["C.OUTPUT"].tolist() == [[1, 2, 3], [4, 5, 6]]
    assert s.plan.arrays["Sub.K.OUTPUT"].tolist() == [7, 8]


def test_frame_encoding_round_trip():
    a = np.arange(6, dtype=np.float32).reshape(2, 3)
    frame = encode_frame(5, 0.05, [("A.OUTPUT", "raw", a.shape, a.tobytes())])
    n = int.from_bytes(frame[:4], "little")
    header = json.loads(frame[4:4 + n])
    assert header == {"tick": 5, "time": 0.05, "buffers": [
        {"path": "A.OUTPUT", "format": "raw", "shape": [2, 3], "offset": 0, "length": 24}]}
    assert decode_frame(frame)[1]["A.OUTPUT"].tolist() == a.tolist()


# --- the real server ---------------------------------------------------------------------

def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_the_ikaros_command_serves_the_demo():
    port = _free_port()
    proc = subprocess.Popen([sys.executable, "-m", "ikaros", "-w", str(port), DEMO],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    try:
        status = None
        end = time.monotonic() + 30
        while time.monotonic() < end and proc.poll() is None:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/status",
                                            timeout=2) as r:
                    status = json.load(r)
                    break
            except OSError:
                time.sleep(0.1)
        assert status is not None, proc.stderr.read() if proc.poll() is not None else ""
        assert status["state"] == "pause" and status["tick"] == 0
        assert status["file"] == "demo.ikg"
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/network", timeout=5) as r:
            views = json.load(r)["top"]["views"]
        classes = {w["class"] for v in views for w in v["widgets"]}
        assert {"bar-graph", "plot", "table", "grid", "image", "marker", "path", "text",
                "rectangle", "button", "switch", "drop-down-menu", "slider-horizontal",
                "slider-vertical"} <= classes
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            out, err = proc.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            out, err = proc.communicate()
    assert proc.returncode == 0, err
    assert f"http://127.0.0.1:{port}/" in out


def test_a_class_can_carry_its_own_view(tmp_path):
    (tmp_path / "Gauge.ikc").write_text('''<class name="Gauge" description="A test class with a view.">
    <input name="INPUT" description="in"/>
    <output name="OUTPUT" size_set="INPUT" description="out"/>
    <view name="Gauge view">
        <bar-graph x="0" y="0" width="120" height="80" source="OUTPUT" max="5"/>
    </view>
</class>''')
    (tmp_path / "Gauge.py").write_text("from ikaros.module import Module\n\n\n"
                                       "class Gauge(Module):\n"
                                       "    def tick(self):\n"
                                       "        self.OUTPUT[...] = self.INPUT\n")
    (tmp_path / "m.ikg").write_text('''<group name="M">
    <module class="Constant" name="K" data="1 2"/>
    <module class="Gauge" name="G"/>
    <connection source="K.OUTPUT" target="G.INPUT"/>
</group>''')
    net = ikaros.load(str(tmp_path / "m.ikg"))
    try:
        with TestClient(create_app(net)) as client:
            view = client.get("/api/module?path=G").json()["view"]
        assert view["name"] == "Gauge view"
        (widget,) = view["widgets"]
        assert widget["class"] == "bar-graph" and widget["source_path"] == "G.OUTPUT"
    finally:
        net.close()
