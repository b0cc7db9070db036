"""The editor's reach: every way out of the models folder is refused for a model sent
through the web UI, and a file outside is never read, written, imported or quoted; a
model loaded from Python keeps full access."""
from __future__ import annotations

import os
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

SECRET = "TOPSECRET-4711"

START = '<group name="Start"><module class="Constant" name="C" data="1 2"/></group>\n'

EVIL = f'''"""Imported only if the editor could reach outside its folder."""
import os

from ikaros.module import Module, Output

open(os.path.join(os.path.dirname(__file__), "imported.txt"), "w").write("{SECRET}")


class Evil(Module):
    """Must never be imported from the web UI."""
    OUTPUT = Output("x", size_x="1")
'''


@pytest.fixture
def place(tmp_path):
    models, outside = tmp_path / "models", tmp_path / "outside"
    models.mkdir()
    outside.mkdir()
    (models / "start.ikg").write_text(START)
    (models / "data").mkdir()
    (models / "data" / "in.csv").write_text("A\n1\n2\n")
    (outside / "secret.ikg").write_text(
        f'<group name="Secret"><module class="Constant" name="K" data="1"/>'
        f'<!-- {SECRET} --></group>\n')
    (outside / "secret.txt").write_text(f"{SECRET}: root:x:0:0\n")
    (outside / "data.csv").write_text(f"{SECRET}\nnot,a,number\n")
    (outside / "Evil.py").write_text(EVIL)
    os.symlink(outside / "secret.txt", models / "link.csv")
    os.symlink(outside, models / "door")
    return models, outside


@pytest.fixture
def client(place):
    models, _ = place
    net = ikaros.load(str(models / "start.ikg"))
    net.log_level = WARNING
    app = create_app(net, models_dir=str(models))
    with TestClient(app) as c:
        yield c
    current = app.state.ui.net
    for n in {net, current}:
        n.controller.stop()
        n.controller.join(5)
        n.close()


def _tree(*children):
    return {"tag": "group", "attrs": {"name": "Start"}, "children": list(children)}


def _module(cls, name, **attrs):
    return {"tag": "module", "attrs": {"class": cls, "name": name, **attrs}}


def _untouched(outside):
    assert sorted(os.listdir(outside)) == ["Evil.py", "data.csv", "secret.ikg",
                                           "secret.txt"]


def _refused(client, tree, message):
    r = client.post("/api/apply", json={"tree": tree})
    assert r.status_code == 422, r.text
    body = r.json()
    assert body["error"].endswith(message), body["error"]
    assert SECRET not in r.text
    return body


def test_includes_outside_are_refused(client, place):
    models, outside = place
    for name in ("../outside/secret.ikg", str(outside / "secret.ikg"), "door/secret.ikg",
                 "~/secret.ikg"):
        tree = _tree({"tag": "#include", "attrs": {"file": name}})
        r = client.post("/api/apply", json={"tree": tree})
        assert r.status_code == 422, r.text
        assert f'<#include>: included file "{name}" is refused: ' in r.json()["error"]
        assert SECRET not in r.text
    _untouched(outside)


@pytest.mark.parametrize("name, why", [
    ("../outside/secret.ikg", 'a model from the web UI may only name files by a relative '
                              'path without ".."'),
    ("/outside/secret.ikg", 'a model from the web UI may only name files by a relative '
                            'path without ".."'),
    ("door/secret.ikg", "it is outside the models folder"),
])
def test_externals_outside_are_refused(client, place, name, why):
    _, outside = place
    if name.startswith("/outside"):
        name = str(outside / "secret.ikg")
    body = _refused(client, _tree({"tag": "group", "attrs": {"name": "G", "external": name}}),
                    f'<group name="G">: group file "{name}" is refused: {why}')
    assert body["path"] == [0]
    _untouched(outside)


@pytest.mark.parametrize("path", ["../outside", "door", "/abs"])
def test_class_folders_outside_are_refused_and_nothing_is_imported(client, place, path):
    _, outside = place
    if path == "/abs":
        path = str(outside)
    _refused(client, _tree(_module("Evil", "E", path=path)), f'class path "{path}" is refused: '
             + ("it is outside the models folder" if path == "door" else
                'a model from the web UI may only name files by a relative path without ".."'))
    _untouched(outside)


@pytest.mark.parametrize("cls, param, name", [
    ("InputCSV", "filename", "../outside/data.csv"),
    ("InputCSV", "filename", "link.csv"),
    ("InputCSV", "filename", "/etc/passwd"),
    ("InputFile", "filename", "door/secret.txt"),
    ("OutputFile", "filename", "../outside/written.txt"),
    ("OutputFile", "directory", "../outside/run"),
    ("OutputCSV", "filename", "door/written.csv"),
])
def test_file_parameters_outside_are_refused(client, place, cls, param, name):
    _, outside = place
    source = _module("Constant", "K", data="1 2")
    module = _module(cls, "F", **{param: name})
    inputs = [] if cls.startswith("Input") else [
        {"tag": "connection", "attrs": {"source": "K.OUTPUT", "target": "F.INPUT"}}]
    body = _refused(client, _tree(source, module, *inputs),
                    f'parameter "{param}" "{name}" is refused: ' +
                    ("it is outside the models folder" if name in ("link.csv",) or
                     name.startswith("door") else
                     'a model from the web UI may only name files by a relative path '
                     'without ".."'))
    assert body["path"] == [1]
    _untouched(outside)


def test_a_file_inside_the_models_folder_is_used(client, place):
    tree = _tree(_module("InputCSV", "F", filename="data/in.csv"))
    r = client.post("/api/apply", json={"tree": tree})
    assert r.status_code == 200, r.text


def test_a_file_parameter_set_while_running_is_confined(client, place):
    models, outside = place
    tree = _tree(_module("InputCSV", "F", filename="data/in.csv"))
    r = client.post("/api/apply", json={"tree": tree})
    assert r.status_code == 200, r.text
    for value in ("/etc/passwd", "../outside/x.txt", "door/x.txt"):
        r = client.post("/api/parameter", json={"path": "F.filename", "value": value})
        assert r.status_code == 403, r.text
        assert r.json()["error"].startswith(f'parameter "filename" "{value}" is refused')
    r = client.post("/api/parameter", json={"path": "F.filename", "value": "data/in.csv"})
    assert r.status_code == 200, r.text
    _untouched(outside)


def test_open_and_save_stay_in_the_models_folder(client, place):
    _, outside = place
    for name in ("../outside/secret.ikg", str(outside / "secret.ikg"), "door/secret.ikg"):
        assert client.post("/api/open", json={"filename": name}).status_code == 403
        tree = client.get("/api/model").json()["tree"]
        assert client.post("/api/save", json={"tree": tree, "filename": name}).status_code \
            == 403
    _untouched(outside)


def test_a_model_loaded_from_python_keeps_full_access(place):
    models, outside = place
    (models / "free.ikg").write_text(
        '<group name="Free"><group name="S" external="../outside/secret.ikg"/>'
        '<module class="Evil" name="E" path="../outside"/></group>')
    net = ikaros.load(str(models / "free.ikg"))
    try:
        assert set(net.modules) == {"S.K", "E"}
        assert (outside / "imported.txt").read_text() == SECRET
    finally:
        net.close()
