"""The run tools of the HTTP API (ikaros/webui/state.py): state save, load and reset, the
profiling window, the start-up steps, quit, and fast-forward."""
from __future__ import annotations

import json
import time
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

MODEL = """<group name="T">
    <module class="FunctionGenerator" name="F" type="ramp" frequency="0.1"/>
    <group name="Sub">
        <module class="Scale" name="S" factor="2"/>
    </group>
    <connection source="F.OUTPUT" target="Sub.S.INPUT" delay="2"/>
</group>"""


@pytest.fixture
def client(tmp_path):
    (tmp_path / "t.ikg").write_text(MODEL)
    net = ikaros.load(str(tmp_path / "t.ikg"))
    net.log_level = WARNING
    app = create_app(net)
    with TestClient(app) as c:
        c.ui = app.state.ui
        yield c
    ui = app.state.ui
    ui.net.controller.stop()
    ui.net.controller.join(5)
    ui.net.close()


def steps(c, n):
    for _ in range(n):
        tick = c.get("/api/status").json()["tick"]
        assert c.post("/api/control", json={"state": "step"}).status_code == 200
        deadline = time.monotonic() + 10
        while c.get("/api/status").json()["tick"] < tick + 1:
            assert time.monotonic() < deadline
            time.sleep(0.01)


def values(c):
    return c.get("/api/data?paths=F.OUTPUT,Sub.S.OUTPUT").json()["data"]


def test_state_save_load_and_reset(client, tmp_path):
    c = client
    steps(c, 4)
    saved = values(c)
    r = c.post("/api/state", json={"action": "save"})
    assert r.json() == {"ok": True, "action": "save", "tick": 4, "scope": "network",
                        "file": "t.state", "item_count": 3}
    assert json.loads((tmp_path / "t.state").read_text())["tick"] == 4
    steps(c, 1)
    next_tick = values(c)
    steps(c, 2)
    assert values(c) != saved
    r = c.post("/api/state", json={"action": "load", "filename": "t.state"})
    assert r.status_code == 200 and r.json()["tick"] == 4
    assert values(c) == saved and c.get("/api/status").json()["tick"] == 4
    steps(c, 1)                      # runs on from there: the delay line was restored too
    assert values(c) == next_tick
    r = c.post("/api/state", json={"action": "reset"})
    assert r.json() == {"ok": True, "action": "reset", "tick": 0, "scope": "network"}
    assert values(c) == {"F.OUTPUT": [0.0], "Sub.S.OUTPUT": [0.0]}

    # one group's state
    steps(c, 2)
    r = c.post("/api/state", json={"action": "save", "filename": "sub.state", "scope": "Sub"})
    assert r.json()["item_count"] == 1 and r.json()["scope"] == "Sub"
    assert c.post("/api/state", json={"action": "load", "filename": "sub.state"}).json() == \
        {"error": 'the file holds the state of "Sub", not of "network"'}

    # refusals
    for body, status in (({"action": "save", "filename": "../x.state"}, 403),
                         ({"action": "save", "filename": "x.ikg"}, 403),
                         ({"action": "load", "filename": "none.state"}, 404),
                         ({"action": "save", "scope": "Nope"}, 404),
                         ({"action": "reset", "filename": "t.state"}, 422),
                         ({"action": "sleep"}, 400)):
        assert c.post("/api/state", json=body).status_code == status, body
    (tmp_path / "bad.state").write_text(json.dumps({"format": "ikaros-state-v1",
                                                    "scope": "network", "items": {}}))
    r = c.post("/api/state", json={"action": "load", "filename": "bad.state"})
    assert r.status_code == 422 and "missing: F.OUTPUT, F.OUTPUT@delay, Sub.S.OUTPUT" in \
        r.json()["error"]


def test_a_scoped_load_answers_where_it_loaded_and_file_names_may_hold_and_equals(tmp_path):
    (tmp_path / "two.ikg").write_text('<group name="T"><module class="Constant" name="A" '
                                      'data="1, 2"/><module class="Constant" name="B" '
                                      'data="3, 4"/></group>')
    net = ikaros.load(str(tmp_path / "two.ikg"))
    net.log_level = WARNING
    with TestClient(create_app(net)) as c:
        name = "run a&b=c (2).state"
        r = c.post("/api/state", json={"action": "save", "filename": name, "scope": "A"})
        assert r.json()["file"] == name and (tmp_path / name).is_file()
        r = c.post("/api/state", json={"action": "load", "filename": name, "scope": "B"})
        assert r.json() == {"ok": True, "action": "load", "tick": 0, "scope": "B",
                            "file": name, "item_count": 1}
        assert c.get("/api/data?paths=B.OUTPUT").json()["data"] == {"B.OUTPUT": [1.0, 2.0]}
        for refused in ("a/b.state", "..&.state", ".a=b.state", "a\\b.state", "a?b.state"):
            r = c.post("/api/state", json={"action": "save", "filename": refused})
            assert r.status_code == 403, refused
    net.close()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run a&b=c (2).state", "two.ikg"]


def test_profiling_startup_quit_and_fast_forward(client):
    c = client
    assert c.get("/api/profiling").json() == {
        "on": False, "modules": [
            {"module": "F", "class": "FunctionGenerator", "count": 0, "mean": 0.0,
             "max": 0.0, "total": 0.0},
            {"module": "Sub.S", "class": "Scale", "count": 0, "mean": 0.0, "max": 0.0,
             "total": 0.0}]}
    assert c.post("/api/profiling", json={"on": True}).json()["on"] is True
    steps(c, 3)
    rows = c.get("/api/profiling").json()["modules"]
    assert [r["count"] for r in rows] == [3, 3]
    assert rows[0]["total"] >= rows[1]["total"] > 0
    assert c.post("/api/profiling", json={"on": "yes"}).status_code == 400

    startup = c.get("/api/startup").json()
    assert [s["step"] for s in startup["steps"]][-1] == "init of the modules"
    assert abs(startup["total"] - sum(s["seconds"] for s in startup["steps"])) < 1e-9

    # fast-forward runs ticks; pausing shows the last one
    assert c.post("/api/control", json={"state": "fastforward"}).json()["state"] == \
        "fastforward"
    deadline = time.monotonic() + 10
    while c.get("/api/status").json()["tick"] < 50:
        assert time.monotonic() < deadline
        time.sleep(0.02)
    c.post("/api/control", json={"state": "pause"})
    assert c.get("/api/status").json()["stop_tick"] is None

    # an app that serve() did not start can not quit
    assert c.post("/api/quit", json={}).status_code == 409
    quits = []
    c.ui.on_quit = lambda: quits.append(1)
    assert c.post("/api/quit", json={}).json() == {"ok": True} and quits == [1]


def test_a_group_of_groups_gets_a_default_view_of_its_subgroups(tmp_path):
    (tmp_path / "g.ikg").write_text("""<group name="Top">
    <group name="A"><module class="Constant" name="K" data="1 2"/>
        <group name="Deep"><module class="Constant" name="D" data="3"/></group></group>
    <group name="B"><module class="Constant" name="L" data="4"/></group>
</group>""")
    net = ikaros.load(str(tmp_path / "g.ikg"))
    with TestClient(create_app(net)) as c:
        top = c.get("/api/network").json()["top"]
        (view,) = top["views"]
        assert view["default"] is True
        assert [(w["source"], w["source_path"], w["x"], w["y"]) for w in view["widgets"]] == [
            ("A.K.OUTPUT", "A.K.OUTPUT", 20, 20), ("B.L.OUTPUT", "B.L.OUTPUT", 240, 20)]
        a = next(g for g in top["groups"] if g["name"] == "A")
        assert [w["source"] for w in a["views"][0]["widgets"]] == ["K.OUTPUT"]
    net.close()
