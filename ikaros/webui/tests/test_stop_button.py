"""The web UI's stop ends the run as the end of a batch run does: every module's stop() is
called once, at once; play, step, real time or pause then run the model again from tick 0
(as Ikaros 3 reloads its file), and the UI can apply, open or reload a model."""
from __future__ import annotations

import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.testing import wait_for  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

STOPWATCH = '''import os

from ikaros.module import Module, Output


class Stopwatch(Module):
    """Test class: counts its ticks; stop() appends "path tick" to stops.txt beside it."""
    TICKS = Output("ticks run", size="1")

    def tick(self):
        self.TICKS[0] += 1

    def stop(self):
        with open(os.path.join(os.path.dirname(__file__), "stops.txt"), "a") as f:
            f.write(f"{self.path} {self.clock.tick}\\n")
'''

MODEL = """<group name="W">
    <module class="Stopwatch" name="A" />
    <module class="Stopwatch" name="B" />
</group>
"""


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "Stopwatch.py").write_text(STOPWATCH)
    (tmp_path / "w.ikg").write_text(MODEL)
    return tmp_path


@pytest.fixture
def client(folder):
    net = ikaros.load(str(folder / "w.ikg"))
    net.log_level = WARNING
    app = create_app(net)
    with TestClient(app) as c:
        yield c
    current = app.state.ui.net
    current.controller.stop()
    current.controller.join(5)
    current.close()


def stops(folder) -> list[str]:
    path = folder / "stops.txt"
    return path.read_text().splitlines() if path.exists() else []


def test_stop_calls_every_modules_stop_once_before_it_answers(client, folder):
    net = client.app.state.ui.net
    assert client.post("/api/control", json={"state": "play"}).status_code == 200
    assert wait_for(lambda: net.tick >= 3)
    r = client.post("/api/control", json={"state": "stop"})
    assert r.status_code == 200 and r.json()["state"] == "stop"
    tick = r.json()["tick"]
    assert stops(folder) == [f"A {tick - 1}", f"B {tick - 1}"]      # the last tick run
    assert net.stopped and not net.controller.running
    assert client.get("/api/status").json()["state"] == "stop"
    assert client.post("/api/control", json={"state": "stop"}).status_code == 409
    net.close()
    assert len(stops(folder)) == 2                                    # never twice


def test_play_after_a_stop_runs_the_model_again_from_tick_0_with_its_edits(client, folder):
    client.post("/api/control", json={"state": "step"})
    assert wait_for(lambda: client.get("/api/status").json()["tick"] == 1)
    tree = client.get("/api/model").json()["tree"]
    tree["children"].append({"tag": "module", "attrs": {"class": "Stopwatch", "name": "C"}})
    assert client.post("/api/apply", json={"tree": tree}).status_code == 200   # not saved
    assert client.post("/api/control", json={"state": "stop"}).status_code == 200
    # the applied network goes on from tick 1 (Apply keeps the state), so its last tick is
    # 0; A and B went on in it (the network Apply replaced did not stop them): each stops once
    assert stops(folder) == ["A 0", "B 0", "C 0"]
    old = client.app.state.ui.net
    assert client.post("/api/control", json={"state": "step"}).status_code == 200
    net = client.app.state.ui.net
    assert net is not old and not net.stopped
    assert wait_for(lambda: net.tick == 1)
    assert net.output("C.TICKS").tolist() == [1]                      # the applied edit is kept
    assert len(stops(folder)) == 3


def test_stop_before_any_tick_ends_the_run_too(client, folder):
    r = client.post("/api/control", json={"state": "stop"})
    assert (r.status_code, r.json()["state"], r.json()["tick"]) == (200, "stop", 0)
    assert stops(folder) == ["A -1", "B -1"]                          # clock.tick of init


def test_after_a_stop_the_model_can_be_reloaded_applied_and_run(client, folder):
    client.post("/api/control", json={"state": "step"})
    assert wait_for(lambda: client.get("/api/status").json()["tick"] == 1)
    client.post("/api/control", json={"state": "stop"})
    assert len(stops(folder)) == 2
    r = client.post("/api/open", json={"filename": "w.ikg"})            # reload
    assert r.status_code == 200, r.text
    assert len(stops(folder)) == 2                                      # the old run: once
    assert client.post("/api/control", json={"state": "step"}).status_code == 200
    assert wait_for(lambda: client.get("/api/status").json()["tick"] == 1)
    tree = client.get("/api/model").json()["tree"]
    r = client.post("/api/apply", json={"tree": tree, "state": "play"})
    assert r.status_code == 200, r.text
    # apply closed the reloaded network, whose modules went on in the new one: not stopped
    assert len(stops(folder)) == 2
    net = client.app.state.ui.net
    assert wait_for(lambda: net.output("A.TICKS")[0] >= 3)
