"""The editor's Apply keeps the state of the modules that did not change (the kernel's
ikaros/kernel/carry.py, which net.apply uses too)."""
import time
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")
import ikaros  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

MODEL = """<?xml version="1.0"?>
<group name="K">
    <module class="Constant" name="One" data="1" />
    <module class="Integrator" name="Sum" alpha="1" beta="1" />
    <connection source="One.OUTPUT" target="Sum.INPUT" />
</group>
"""


def _wait(condition, timeout=10.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.02)
    return False


def test_apply_of_an_unrelated_change_keeps_an_integrators_sum(tmp_path):
    path = tmp_path / "k.ikg"
    path.write_text(MODEL)
    net = ikaros.load(str(path))
    app = create_app(net)
    with TestClient(app) as client:
        for n in (1, 2, 3, 4):
            client.post("/api/control", json={"state": "step"})
            assert _wait(lambda: client.get("/api/status").json()["tick"] >= n)
        tree = client.get("/api/model").json()["tree"]
        tree["children"].append({"tag": "module", "attrs": {"class": "Sweep", "name": "New"},
                                 "children": []})
        r = client.post("/api/apply", json={"tree": tree})
        assert r.status_code == 200, r.text
        assert client.get("/api/status").json()["tick"] == 4
        assert client.get("/api/data", params={"paths": "Sum.OUTPUT"}).json()["data"] == \
            {"Sum.OUTPUT": [4]}
        client.post("/api/control", json={"state": "step"})
        assert _wait(lambda: client.get("/api/status").json()["tick"] >= 5)
        assert client.get("/api/data", params={"paths": "Sum.OUTPUT"}).json()["data"] == \
            {"Sum.OUTPUT": [5]}
        app.state.ui.net.controller.stop()
    app.state.ui.net.close()


ADDING = """<?xml version="1.0"?>
<group name="A">
    <module class="Sweep" name="Ramp" min="0" max="100" step="1" />
    <module class="Sweep" name="Ramp2" min="0" max="100" step="10" />
    <module class="Add" name="Add" />
    <connection source="Ramp.OUTPUT" target="Add.INPUT1" delay="0" />
    <connection source="Ramp2.OUTPUT" target="Add.INPUT2" delay="0" />
</group>
"""


def test_after_apply_add_follows_its_inputs(tmp_path):
    """Issue 37: after Apply, Add went on adding the inputs of the replaced network."""
    path = tmp_path / "a.ikg"
    path.write_text(ADDING)
    net = ikaros.load(str(path))
    app = create_app(net)

    def step_to(n):
        client.post("/api/control", json={"state": "step"})
        assert _wait(lambda: client.get("/api/status").json()["tick"] >= n)

    def value(path):
        return client.get("/api/data", params={"paths": path}).json()["data"][path]

    with TestClient(app) as client:
        for n in (1, 2, 3):
            step_to(n)
        tree = client.get("/api/model").json()["tree"]
        tree["children"].insert(0, {"tag": "module", "children": [],
                                    "attrs": {"class": "Constant", "name": "New",
                                              "data": "1 2 3"}})
        assert client.post("/api/apply", json={"tree": tree}).status_code == 200
        for n in (4, 5, 6):
            step_to(n)
            assert value("Ramp.OUTPUT") == [n] and value("Ramp2.OUTPUT") == [10 * n]
            assert value("Add.OUTPUT") == [11 * n]
        app.state.ui.net.controller.stop()
    app.state.ui.net.close()
