"""Details of the hardened HTTP API: one Origin with its scheme, bodies streamed past the
limit, parameter values checked as in a model file (finite, in range), saved files keep
their mode, and what the UI is told once the run has ended."""
from __future__ import annotations

import os
import stat
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

MODEL = '''<group name="H">
    <module class="Sweep" name="S" step="0.5" />
    <module class="Constant" name="C" data="1 2" />
</group>
'''


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "h.ikg").write_text(MODEL)
    return tmp_path


@pytest.fixture
def client(folder):
    net = ikaros.load(str(folder / "h.ikg"))
    net.log_level = WARNING
    app = create_app(net, max_body=1000)
    with TestClient(app) as c:
        yield c
    for n in {net, app.state.ui.net}:
        n.controller.stop()
        n.controller.join(5)
        n.close()


@pytest.mark.parametrize("origins, status", [
    ([], 200),
    (["http://testserver"], 200),
    (["https://testserver"], 403),
    (["ftp://testserver"], 403),
    (["testserver"], 403),
    (["http://testserver", "http://testserver"], 403),
    (["http://testserver", "http://evil.example"], 403),
])
def test_one_origin_with_the_servers_scheme_host_and_port(client, origins, status):
    headers = [("origin", o) for o in origins]
    r = client.post("/api/control", json={"state": "pause"}, headers=headers)
    assert r.status_code == status, r.text
    if status == 403:
        assert r.json() == {"error": "cross-origin request refused"}


def test_a_streamed_body_over_the_limit_is_413(client):
    def chunks():
        for _ in range(20):
            yield b" " * 100
    r = client.post("/api/control", content=chunks(),
                    headers={"content-type": "application/json"})
    assert (r.status_code, r.json()) == (413, {
        "error": "the request body is larger than the limit of 1000 bytes"})
    r = client.post("/api/control", content=b" " * 2000,
                    headers={"content-type": "application/json"})
    assert r.status_code == 413


@pytest.mark.parametrize("value, reason", [
    ("nan", "nan is not a finite number"),
    ("1e400", "inf is not a finite number"),
    ("-inf", "-inf is not a finite number"),
])
def test_parameters_set_from_the_ui_must_be_finite(client, value, reason):
    r = client.post("/api/parameter", json={"path": "S.step", "value": value})
    assert (r.status_code, r.json()) == (422, {
        "error": f'bad value for parameter "S.step": {reason}'})
    assert client.app.state.ui.net.parameter("S.step") == 0.5


def test_a_saved_file_keeps_its_mode_and_a_new_one_gets_the_umask(client, folder):
    os.chmod(folder / "h.ikg", 0o640)
    tree = client.get("/api/model").json()["tree"]
    assert client.post("/api/save", json={"tree": tree}).status_code == 200
    assert stat.S_IMODE(os.stat(folder / "h.ikg").st_mode) == 0o640
    umask = os.umask(0o022)
    os.umask(umask)
    r = client.post("/api/save", json={"tree": tree, "filename": "copy.ikg"})
    assert r.status_code == 200
    assert stat.S_IMODE(os.stat(folder / "copy.ikg").st_mode) == 0o666 & ~umask


def test_lone_surrogates_quoted_back_are_json_escapes_not_500(client):
    r = client.post("/api/parameter", content=b'{"path": "\\ud800.x", "value": 1}',
                    headers={"content-type": "application/json"})
    assert r.status_code == 404
    assert r.content == b'{"error":"no parameter \\"\\ud800.x\\" in H"}'
    assert r.json() == {"error": 'no parameter "\ud800.x" in H'}


def test_after_the_run_has_ended_the_ui_is_told_what_to_do(client):
    net = client.app.state.ui.net
    net.controller.stop()
    net.controller.join(5)
    net.close()
    r = client.post("/api/control", json={"state": "play"})
    assert (r.status_code, r.json()) == (409, {
        "error": "the run has ended; apply, open or reload a model to run again"})
