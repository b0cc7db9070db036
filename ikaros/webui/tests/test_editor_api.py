"""The editor's endpoints: the model tree, apply (a rebuild, or the kernel's error located at
the element at fault with the old network still running), save and save-as with the folder
rule, files, open and new; and every conformance model through GET /api/model and
POST /api/save."""
from __future__ import annotations

import glob
import hashlib
import json
import os
import shutil
import time
import warnings

import numpy as np
import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
CONFORMANCE = os.path.join(ROOT, "tests", "conformance", "models")
GOOD = sorted(os.path.basename(p) for p in glob.glob(os.path.join(CONFORMANCE, "*.ikg"))
              if not os.path.basename(p).startswith("err_"))

MODEL = """<?xml version="1.0"?><!-- before the model -->
<group name="E" tick_duration="0.01" mystery="kept">
    <!-- a comment inside the model -->
    <module class="Constant" name="C" data="1 2 3" color="red" _x="10" _y="20" />
    <module class="Scale" name="S" factor="2" />
    <connection source="C.OUTPUT" target="S.INPUT" delay="0" />
    <note author="me" lang="en">A <b>free</b> element the kernel does not know</note>
    <?include file="part.xml"?>
    <view name="V">
        <plot source="S.OUTPUT" x="0" y="0" odd="1" />
    </view>
</group>
<!-- after the model -->
"""

PART = """<module class="Constant" name="P" data="5" />
<!-- inside the include -->
<module class="Scale" name="PS" factor="3" />
<connection source="P.OUTPUT" target="PS.INPUT" delay="0" />
"""

OTHER = """<?xml version="1.0"?>
<group name="Other">
    <module class="Constant" name="K" data="7 8" />
</group>
"""

BAD = """<?xml version="1.0"?>
<group name="Bad">
    <module class="NoSuchClass" name="K" />
</group>
"""


@pytest.fixture
def folder(tmp_path):
    d = tmp_path / "models"
    d.mkdir()
    (d / "e.ikg").write_text(MODEL)
    (d / "part.xml").write_text(PART)
    (d / "other.ikg").write_text(OTHER)
    (d / "bad.ikg").write_text(BAD)
    (d / "bad_part.xml").write_text('<module class="Nope" name="Q" />\n')
    return d


@pytest.fixture
def net(folder):
    n = ikaros.load(str(folder / "e.ikg"))
    n.log_level = WARNING
    yield n
    n.controller.stop()
    n.controller.join(5)
    n.close()


def _app(net, **options):
    app = create_app(net, **options)
    return app


@pytest.fixture
def app(net):
    a = _app(net)
    yield a
    current = a.state.ui.net
    if current is not net:
        current.controller.stop()
        current.controller.join(5)
        current.close()


@pytest.fixture
def client(app):
    with TestClient(app) as c:
        yield c


def _error(r, status):
    assert r.status_code == status, (r.status_code, r.text)
    body = r.json()
    assert body["error"]
    return body


def _wait(predicate, timeout=10.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.01)
    return False


def _nodes(tree, path=()):
    yield path, tree
    for i, child in enumerate(tree.get("children", [])):
        yield from _nodes(child, path + (i,))


def _find(tree, tag, name=None):
    for path, node in _nodes(tree):
        if node["tag"] == tag and (name is None or node["attrs"].get("name") == name):
            return list(path), node
    raise KeyError((tag, name))


def _outputs(net):
    out = {}
    for inst in net.schedule:
        for spec in inst.module.description.outputs:
            out[f"{inst.path}.{spec.name}"] = net.output(f"{inst.path}.{spec.name}")
    return out


def _same_network(a, b, ticks=4):
    """Same modules, connections and outputs over a few ticks."""
    oa, ob = _outputs(a), _outputs(b)
    assert oa.keys() == ob.keys()
    assert a.info().split("Connections:")[1] == b.info().split("Connections:")[1]
    for _ in range(ticks):
        for path in oa:
            assert np.array_equal(a.output(path), b.output(path)), path
        a.step()
        b.step()


def _snapshot(folder):
    return {p: open(p, "rb").read() for p in glob.glob(os.path.join(folder, "**"),
                                                        recursive=True)
            if os.path.isfile(p)}


# --- the tree ----------------------------------------------------------------------------

def test_model_tree(client, folder):
    m = client.get("/api/model").json()
    assert m["file"] == "e.ikg" and m["folder"] == str(folder)
    tree = m["tree"]
    ids = [n["id"] for _, n in _nodes(tree)]
    assert ids == list(range(1, len(ids) + 1))
    assert tree["tag"] == "group" and tree["file"] == "e.ikg" and tree["line"] == 2
    assert list(tree["attrs"]) == ["name", "tick_duration", "mystery"]
    assert tree["outside"] == {"before": [" before the model "], "after": [" after the model "]}
    kinds = [c["tag"] for c in tree["children"]]
    assert kinds == ["#comment", "module", "module", "connection", "note", "#include", "view"]
    comment, c = tree["children"][0], tree["children"][1]
    assert comment["text"] == " a comment inside the model "
    assert list(c["attrs"]) == ["class", "name", "data", "color", "_x", "_y"]
    assert (c["file"], c["line"]) == ("e.ikg", 4)
    inc = tree["children"][5]
    assert inc["attrs"] == {"file": "part.xml"}
    assert [(k["tag"], k["file"], k["line"]) for k in inc["children"]] == [
        ("module", "part.xml", 1), ("#comment", "part.xml", 2), ("module", "part.xml", 3),
        ("connection", "part.xml", 4)]
    _error(client.get("/api/model", params={"x": "1"}), 400)


def test_save_unchanged_keeps_everything_and_loads_to_the_same_network(client, net, folder):
    before = (folder / "e.ikg").read_text()
    tree = client.get("/api/model").json()["tree"]
    r = client.post("/api/save", json={"tree": tree})
    text = (folder / "e.ikg").read_text()
    assert r.status_code == 200 and r.json() == {"ok": True, "file": "e.ikg", "version": (
        hashlib.sha256(text.encode()).hexdigest()[:20])}        # the version of the file
    assert text.startswith('<?xml version="1.0"?>\n<!-- before the model -->\n<group name="E"')
    assert text.endswith('</group>\n<!-- after the model -->\n') and before
    for kept in ('<!-- a comment inside the model -->', 'mystery="kept"', 'color="red"',
                 '_x="10"', '<note author="me" lang="en">', '<b>free</b>',
                 '<?include file="part.xml"?>', 'odd="1"'):
        assert kept in text, kept
    assert 'name="PS"' not in text                 # the include, not its contents
    assert (folder / "part.xml").read_text() == PART
    again = ikaros.load(str(folder / "e.ikg"))
    try:
        _same_network(net, again)
    finally:
        again.close()
    # saving the saved tree again gives the same text
    tree2 = client.get("/api/model").json()["tree"]
    client.post("/api/save", json={"tree": tree2, "filename": "e2.ikg"})
    assert (folder / "e2.ikg").read_text() == text


def test_save_as_and_the_writer_keep_attribute_order(client, folder):
    tree = client.get("/api/model").json()["tree"]
    _, c = _find(tree, "module", "C")
    c["attrs"] = {"_y": "5", "name": "C", "class": "Constant", "data": "4 5 6", "_x": 7}
    r = client.post("/api/save", json={"tree": tree, "filename": "copy.ikg"})
    assert r.json()["ok"] is True and r.json()["file"] == "copy.ikg"
    text = (folder / "copy.ikg").read_text()
    assert '<module _y="5" name="C" class="Constant" data="4 5 6" _x="7"/>' in text
    saved = ikaros.load(str(folder / "copy.ikg"))
    try:
        saved.step()
        assert saved.output("S.OUTPUT").tolist() == [8, 10, 12]
    finally:
        saved.close()
    # saving does not rebuild; the model's file is the new one now
    assert client.get("/api/status").json()["file"] == "copy.ikg"
    assert client.get("/api/model").json()["file"] == "copy.ikg"
    assert client.get("/api/data", params={"paths": "C.OUTPUT"}).json()["data"] == {
        "C.OUTPUT": [1, 2, 3]}
    before = (folder / "e.ikg").read_text()
    c["attrs"]["data"] = "9"
    assert client.post("/api/save", json={"tree": tree}).json()["file"] == "copy.ikg"
    assert 'data="9"' in (folder / "copy.ikg").read_text()
    assert (folder / "e.ikg").read_text() == before


# --- apply -------------------------------------------------------------------------------

def test_apply_a_valid_edit_rebuilds(client, app, net):
    client.post("/api/control", json={"state": "step"})
    assert _wait(lambda: client.get("/api/status").json()["tick"] >= 1)
    tree = client.get("/api/model").json()["tree"]
    tree["children"] += [
        {"tag": "module", "attrs": {"class": "Scale", "name": "S2", "factor": "10",
                                    "_x": "300", "_y": "40"}},
        {"tag": "connection", "attrs": {"source": "S.OUTPUT", "target": "S2.INPUT",
                                        "delay": "0"}},
    ]
    with client.websocket_connect("/api/ws") as ws:
        r = client.post("/api/apply", json={"tree": tree, "state": "pause"})
        assert r.status_code == 200, r.text
        body = r.json()
        assert body["ok"] is True
        assert "S2" in [m["name"] for m in body["network"]["top"]["modules"]]
        for _ in range(20):
            msg = json.loads(ws.receive_text())
            if msg["type"] == "network":
                break
        else:
            raise AssertionError("no network message")
    new = app.state.ui.net
    assert new is not net and net.stopped           # the old one is closed
    assert new.filename == net.filename
    top = client.get("/api/network").json()["top"]
    assert "S2" in [m["name"] for m in top["modules"]]
    assert {"source": "S.OUTPUT", "target": "S2.INPUT", "delay": "0"} in top["connections"]
    status = client.get("/api/status").json()
    assert status["state"] == "pause" and status["tick"] == net.tick   # goes on from its tick
    client.post("/api/control", json={"state": "step"})
    assert _wait(lambda: client.get("/api/status").json()["tick"] >= 1)
    data = client.get("/api/data", params={"paths": "S2.OUTPUT"}).json()["data"]
    assert data == {"S2.OUTPUT": [20, 40, 60]}
    # the layout attributes are part of the running model's tree
    _, s2 = _find(client.get("/api/model").json()["tree"], "module", "S2")
    assert s2["attrs"]["_x"] == "300" and s2["id"] is not None


def test_apply_keeps_the_run_state_by_default(client, app):
    client.post("/api/control", json={"state": "play"})
    tree = client.get("/api/model").json()["tree"]
    _, s = _find(tree, "module", "S")
    s["attrs"]["factor"] = "3"
    r = client.post("/api/apply", json={"tree": tree})
    assert r.status_code == 200, r.text
    assert client.get("/api/status").json()["state"] == "play"
    assert _wait(lambda: client.get("/api/status").json()["tick"] >= 3)
    data = client.get("/api/data", params={"paths": "S.OUTPUT"}).json()["data"]
    assert data == {"S.OUTPUT": [3, 6, 9]}
    client.post("/api/control", json={"state": "pause"})


def _cycle(tree):
    """S.OUTPUT -> T.INPUT -> S.INPUT, all without delay (S is also fed by C)."""
    tree["children"] += [
        {"tag": "module", "attrs": {"class": "Scale", "name": "T"}},
        {"tag": "connection", "attrs": {"source": "S.OUTPUT", "target": "T.INPUT",
                                        "delay": "0"}},
        {"tag": "connection", "attrs": {"source": "T.OUTPUT", "target": "S.INPUT",
                                        "delay": "0"}},
    ]
    n = len(tree["children"])
    return [[n - 2], [n - 1]], "connection", "zero-delay cycle"


def _unconnected(tree):
    tree["children"].append({"tag": "module", "attrs": {"class": "Scale", "name": "Lonely"}})
    return [[len(tree["children"]) - 1]], "module", 'required input "INPUT"'


def _unknown_class(tree):
    tree["children"].append({"tag": "module", "attrs": {"class": "Nope", "name": "N"}})
    return [[len(tree["children"]) - 1]], "module", 'unknown class "Nope"'


@pytest.mark.parametrize("edit", [_cycle, _unconnected, _unknown_class])
def test_apply_an_invalid_edit_names_the_element_and_keeps_running(client, app, net, edit):
    before = client.get("/api/network").json()
    client.post("/api/control", json={"state": "play"})
    tree = client.get("/api/model").json()["tree"]
    paths, tag, words = edit(tree)
    r = client.post("/api/apply", json={"tree": tree})
    body = _error(r, 422)
    assert set(body) == {"error", "node", "path"}
    assert words in body["error"]
    assert body["path"] in paths                   # the element at fault
    node = tree
    for i in body["path"]:
        node = node["children"][i]
    assert node["tag"] == tag and body["node"] is None      # created by the app: no id
    assert app.state.ui.net is net and not net.stopped
    t = client.get("/api/status").json()["tick"]
    assert _wait(lambda: client.get("/api/status").json()["tick"] > t + 2)
    assert client.get("/api/status").json()["state"] == "play"
    client.post("/api/control", json={"state": "pause"})
    assert client.get("/api/network").json() == before


def test_an_error_at_an_existing_element_gives_its_id(client, app, net):
    tree = client.get("/api/model").json()["tree"]
    path, s = _find(tree, "module", "S")
    s["attrs"]["class"] = "Nope"
    body = _error(client.post("/api/apply", json={"tree": tree}), 422)
    assert body["node"] == s["id"] and body["path"] == path
    assert "e.ikg:5" in body["error"]                       # its line in the file
    tree = client.get("/api/model").json()["tree"]
    path, conn = _find(tree, "connection")
    conn["attrs"]["target"] = "S.NOWHERE"
    body = _error(client.post("/api/apply", json={"tree": tree}), 422)
    assert body["node"] == conn["id"] and body["path"] == path
    assert app.state.ui.net is net


def test_errors_in_includes_point_at_the_include(client, app, net):
    tree = client.get("/api/model").json()["tree"]
    path, inc = _find(tree, "#include")
    inc["attrs"]["file"] = "bad_part.xml"
    body = _error(client.post("/api/apply", json={"tree": tree}), 422)
    assert 'unknown class "Nope"' in body["error"] and "bad_part.xml:1" in body["error"]
    assert body["node"] == inc["id"] and body["path"] == path
    inc["attrs"]["file"] = "missing.xml"
    body = _error(client.post("/api/apply", json={"tree": tree}), 422)
    assert "not found" in body["error"] and body["path"] == path
    # an error at an included element unchanged names that element (its file and line)
    tree = client.get("/api/model").json()["tree"]
    path, inc = _find(tree, "#include")
    tree["children"] = [c for c in tree["children"]
                        if c["attrs"].get("name") != "C" and
                        c["attrs"].get("source") != "C.OUTPUT"]
    tree["children"].insert(0, {"tag": "module", "attrs": {"class": "Constant",
                                                           "name": "P"}})
    path, inc = _find(tree, "#include")
    body = _error(client.post("/api/apply", json={"tree": tree}), 422)
    assert 'duplicate name "P"' in body["error"] and "part.xml:1" in body["error"]
    assert body["node"] == inc["children"][0]["id"] and body["path"] == path + [0]
    assert app.state.ui.net is net


def test_apply_refuses_bad_requests(client, app, net):
    tree = client.get("/api/model").json()["tree"]
    good = json.loads(json.dumps(tree))
    bad_trees = [
        [], "group", {"tag": "group", "wat": 1}, {"tag": "no such tag!"},
        {"tag": "group", "attrs": {"a": None}}, {"tag": "group", "attrs": {"a": True}},
        {"tag": "group", "attrs": {"bad name": "1"}}, {"tag": "group", "attrs": []},
        {"tag": "group", "children": {}}, {"tag": "group", "children": [5]},
        {"tag": "group", "id": -1}, {"tag": "group", "id": "1"}, {"tag": "group", "line": 0},
        {"tag": "group", "text": 5}, {"tag": "#comment", "text": "x"},
        {"tag": "module", "attrs": {"class": "Constant"}},
        {"tag": "group", "children": [{"tag": "#comment", "text": "a -- b"}]},
        {"tag": "group", "children": [{"tag": "#include", "attrs": {}}]},
        {"tag": "group", "children": [{"tag": "#include", "attrs": {"file": 'a"b'}}]},
        {"tag": "group", "attrs": {"x": "bell\x07"}},
        {"tag": "group", "outside": []}, {"tag": "group", "outside": {"before": "x"}},
        {"tag": "group", "outside": {"before": ["a -- b"]}},
        {"tag": "group", "outside": {"middle": []}},
        {"tag": "group", "children": [{"tag": "group", "outside": {"before": []}}]},
    ]
    for bad in bad_trees:
        _error(client.post("/api/apply", json={"tree": bad}), 400)
    deep = {"tag": "group"}
    for _ in range(200):
        deep = {"tag": "group", "children": [deep]}
    _error(client.post("/api/apply", json={"tree": deep}), 400)
    _error(client.post("/api/apply", json={}), 400)
    _error(client.post("/api/apply", json={"tree": good, "extra": 1}), 400)
    _error(client.post("/api/apply", json={"tree": good, "state": "stop"}), 400)
    _error(client.post("/api/apply", json={"tree": good, "state": "fast"}), 400)
    _error(client.post("/api/apply", content=json.dumps({"tree": good})), 415)
    _error(client.get("/api/apply"), 405)
    assert app.state.ui.net is net and not net.stopped


# --- save and the folder rule ------------------------------------------------------------

@pytest.mark.parametrize("name", [
    "../x.ikg", "../models/x.ikg", "/tmp/x.ikg", "sub/x.ikg", "sub\\x.ikg", "x.txt", "x",
    "x.ikg.txt", ".ikg", ".hidden.ikg", "..ikg", "..%2Fx.ikg", "%2e%2e%2fx.ikg",
    "..%5cx.ikg", "x.ikg\x00", " x.ikg", "x.ikg ", "", "x.IKG", "C:x.ikg", "~/x.ikg",
    "x" * 300 + ".ikg", "x\n.ikg", "part.xml"])
def test_save_as_outside_the_folder_is_refused(client, folder, tmp_path, name):
    tree = client.get("/api/model").json()["tree"]
    before = _snapshot(str(tmp_path))
    _error(client.post("/api/save", json={"tree": tree, "filename": name}), 403)
    assert _snapshot(str(tmp_path)) == before
    assert not os.path.exists("/tmp/x.ikg") or name != "/tmp/x.ikg"


def test_save_absolute_path_inside_the_folder_is_refused_too(client, folder, tmp_path):
    tree = client.get("/api/model").json()["tree"]
    before = _snapshot(str(tmp_path))
    _error(client.post("/api/save", json={"tree": tree, "filename": str(folder / "y.ikg")}),
           403)
    _error(client.post("/api/save", json={"tree": tree, "filename": 5}), 400)
    _error(client.post("/api/save", json={"tree": tree, "filename": None, "x": 1}), 400)
    _error(client.post("/api/save", json={"tree": {"tag": "module"}}), 400)
    _error(client.post("/api/save", json={"filename": "y.ikg"}), 400)
    assert _snapshot(str(tmp_path)) == before


def test_save_into_the_models_folder_given(net, folder, tmp_path):
    other = tmp_path / "elsewhere"
    other.mkdir()
    (other / "z.ikg").write_text(OTHER)
    app = create_app(net, models_dir=str(other))
    with TestClient(app) as client:
        assert client.get("/api/files").json() == {"folder": str(other), "files": ["z.ikg"]}
        tree = client.get("/api/model").json()["tree"]
        assert client.post("/api/save", json={"tree": tree, "filename": "s.ikg"}).json()[
            "file"] == "s.ikg"
        assert (other / "s.ikg").exists() and not (folder / "s.ikg").exists()
        # saving without a name writes the model's file: the one saved as
        assert client.post("/api/save", json={"tree": tree}).json()["file"] == "s.ikg"
        _error(client.post("/api/save", json={"tree": tree, "filename": "../models/e.ikg"}),
               403)
        r = client.post("/api/open", json={"filename": "z.ikg"})
        assert r.status_code == 200 and r.json()["file"] == "z.ikg"
        assert client.get("/api/model").json()["file"] == "z.ikg"
    current = app.state.ui.net
    current.controller.stop()
    current.controller.join(5)
    current.close()


def test_save_never_follows_a_symlink_out(client, folder, tmp_path):
    outside = tmp_path / "outside.ikg"
    outside.write_text("outside")
    os.symlink(outside, folder / "link.ikg")
    tree = client.get("/api/model").json()["tree"]
    assert client.post("/api/save", json={"tree": tree, "filename": "link.ikg"}).json()[
        "ok"]
    assert outside.read_text() == "outside"
    assert not os.path.islink(folder / "link.ikg")


# --- files, open, new --------------------------------------------------------------------

def test_files(client, folder):
    (folder / "sub").mkdir()
    (folder / "sub" / "deep.ikg").write_text(OTHER)
    (folder / ".hidden.ikg").write_text(OTHER)
    assert client.get("/api/files").json() == {
        "folder": str(folder), "files": ["bad.ikg", "e.ikg", "other.ikg"]}
    _error(client.get("/api/files", params={"q": "1"}), 400)


def test_open(client, app, net, folder):
    r = client.post("/api/open", json={"filename": "other.ikg"})
    assert r.status_code == 200, r.text
    assert r.json()["ok"] and r.json()["file"] == "other.ikg"
    assert r.json()["network"]["name"] == "Other"
    status = client.get("/api/status").json()
    assert status["file"] == "other.ikg" and status["state"] == "pause"
    m = client.get("/api/model").json()
    assert m["file"] == "other.ikg" and m["tree"]["attrs"]["name"] == "Other"
    assert net.stopped
    # an invalid model: the error, and the current one keeps running
    current = app.state.ui.net
    client.post("/api/control", json={"state": "play"})
    body = _error(client.post("/api/open", json={"filename": "bad.ikg"}), 422)
    assert 'unknown class "NoSuchClass"' in body["error"]
    assert body["node"] is None and body["path"] is None
    assert app.state.ui.net is current
    t = client.get("/api/status").json()["tick"]
    assert _wait(lambda: client.get("/api/status").json()["tick"] > t)
    _error(client.post("/api/open", json={"filename": "missing.ikg"}), 404)
    _error(client.post("/api/open", json={"filename": "../models/other.ikg"}), 403)
    _error(client.post("/api/open", json={"filename": "part.xml"}), 403)
    _error(client.post("/api/open", json={"filename": 1}), 400)
    _error(client.post("/api/open", json={}), 400)
    assert app.state.ui.net is current
    client.post("/api/control", json={"state": "pause"})


def test_new(client, app, net, folder):
    r = client.post("/api/new", json={"name": "Fresh"})
    assert r.status_code == 200, r.text
    assert r.json()["file"] == "Fresh.ikg" and r.json()["network"]["name"] == "Fresh"
    assert not (folder / "Fresh.ikg").exists()               # not yet saved
    m = client.get("/api/model").json()
    assert m["file"] == "Fresh.ikg" and m["version"] is None         # no file yet
    tree = m["tree"]
    assert tree["tag"] == "group" and tree["attrs"] == {"name": "Fresh"}
    assert tree["children"] == []
    assert client.get("/api/status").json()["state"] == "pause"
    tree["children"].append({"tag": "module", "attrs": {"class": "Constant", "name": "K",
                                                        "data": "4"}})
    assert client.post("/api/apply", json={"tree": tree}).status_code == 200
    saving = client.post("/api/save", json={"tree": tree, "version": None}).json()
    assert saving["ok"] is True and saving["file"] == "Fresh.ikg"
    saved = ikaros.load(str(folder / "Fresh.ikg"))
    try:
        saved.step()
        assert saved.output("K.OUTPUT").tolist() == [4]
    finally:
        saved.close()
    # the name is taken now: the next new model gets another file
    assert client.post("/api/new", json={"name": "Fresh"}).json()["file"] == "Fresh-2.ikg"
    assert client.post("/api/new", json={}).json()["file"] == "Untitled.ikg"
    for bad in ("", "../x", "a b", "1abc", 5, None):
        _error(client.post("/api/new", json={"name": bad}), 400)
    _error(client.post("/api/new", json={"name": "X", "other": 1}), 400)


def test_openapi_describes_the_editor(client):
    spec = client.get("/api/openapi.json").json()
    for path in ("/api/model", "/api/apply", "/api/save", "/api/files", "/api/open",
                 "/api/new"):
        assert path in spec["paths"]
    assert "Node" in spec["components"]["schemas"]


def test_command_line_models_option(tmp_path, capsys):
    from ikaros.cli import main, parser
    assert parser().parse_args(["--models", str(tmp_path), "x.ikg"]).models == str(tmp_path)
    with pytest.raises(SystemExit) as e:
        main(["--models", str(tmp_path / "nope"), "x.ikg"])
    assert e.value.code == 2


# --- every conformance model -------------------------------------------------------------

@pytest.mark.parametrize("name", GOOD)
def test_conformance_model_saved_from_the_editor_loads_the_same(name, tmp_path):
    folder = tmp_path / "models"
    shutil.copytree(CONFORMANCE, folder)
    original = ikaros.load(str(folder / name))
    original.log_level = WARNING
    app = create_app(original)
    try:
        with TestClient(app) as client:
            tree = client.get("/api/model").json()["tree"]
            saved_name = "saved_" + name
            r = client.post("/api/save", json={"tree": tree, "filename": saved_name})
            assert r.status_code == 200, r.text
        again = ikaros.load(str(folder / saved_name))
        again.log_level = WARNING
        try:
            _same_network(original, again)
        finally:
            again.close()
    finally:
        original.close()


def test_apply_keeps_the_command_line_settings(folder):
    net = ikaros.load(str(folder / "e.ikg"), tick_duration="0.05", threads="2")
    net.stop_tick = 7                                   # ikaros -s 7
    app = create_app(net)
    try:
        with TestClient(app) as client:
            tree = client.get("/api/model").json()["tree"]
            assert "threads" not in tree["attrs"]       # not written into the model
            assert client.post("/api/apply", json={"tree": tree}).status_code == 200
            new = app.state.ui.net
            assert new is not net
            assert new.clock.tick_duration == 0.05 and new.threads == 2
            assert new.stop_tick == 7
            assert client.post("/api/open", json={"filename": "other.ikg"}).status_code == 200
            other = app.state.ui.net
            assert other.clock.tick_duration == 0.01 and other.stop_tick is None
    finally:
        current = app.state.ui.net
        current.controller.stop()
        current.controller.join(5)
        current.close()
        net.close()
