"""/api/record: what a recording would hold, recording chosen outputs every n-th tick, and a
failed start leaving no folder behind (issue 37, item 8)."""
import os
import warnings

import numpy as np
import pytest

pytest.importorskip("h5py")
pytest.importorskip("xarray")
warnings.filterwarnings("ignore", message=".*httpx.*")

from starlette.testclient import TestClient  # noqa: E402

from ikaros.experiments import open_recording  # noqa: E402
from ikaros.experiments import recording  # noqa: E402
from ikaros.testing import load_body  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

BODY = ('<module class="Sweep" name="Counter" step="1" max="1e9"/>'
        '<module class="Constant" name="Table" data="1 2 3; 4 5 6"/>'
        '<module class="Constant" name="One" data="1"/>')


def test_the_endpoint_says_what_a_recording_would_hold(tmp_path):
    net = load_body(tmp_path, BODY, user_data=str(tmp_path / "data"))
    with TestClient(create_app(net)) as client:
        every = client.get("/api/record").json()
        assert (every["outputs"], every["values"]) == (3, 1 + 6 + 1)
        assert every["largest"][0] == ["Table.OUTPUT", 6]
        some = client.get("/api/record", params={"only": "Counter.*, One.OUTPUT"}).json()
        assert (some["outputs"], some["values"]) == (2, 2)
        r = client.get("/api/record", params={"only": "Nothing.*"})
        assert r.status_code == 404 and "Nothing.*" in r.json()["error"]
        r = client.post("/api/record", json={"on": True, "only": ["Nothing.*"]})
        assert r.status_code == 404 and "Nothing.*" in r.json()["error"]
        for bad in ({"on": True, "only": 5}, {"on": True, "every": 0},
                    {"on": True, "every": 1.5}, {"on": True, "every": True}):
            assert client.post("/api/record", json=bad).status_code == 400, bad
        r = client.post("/api/record", content='{"on": true, "every": Infinity}',
                        headers={"Content-Type": "application/json"})
        assert r.status_code == 400
    net.close()
    assert not os.path.exists(tmp_path / "data")         # nothing started, nothing made


def test_a_recording_of_chosen_outputs_every_third_tick(tmp_path):
    data = tmp_path / "data"
    net = load_body(tmp_path, BODY, user_data=str(data))
    with TestClient(create_app(net)) as client:
        state = client.post("/api/record", json={"on": True, "only": ["Counter.*"],
                                                 "every": 3}).json()
        assert state["recording"] and (state["outputs"], state["values"], state["every"]) == (1, 1, 3)
        net.run(ticks=12)
        client.post("/api/record", json={"on": False})
    net.close()
    ds = open_recording(str(data / state["file"]))
    assert [v for v in ds.data_vars if v.endswith("OUTPUT")] == ["Counter.OUTPUT"]
    assert set(np.diff(ds["tick"].values)) == {3}


def test_record_without_h5py_makes_no_folder(tmp_path, monkeypatch):
    def missing():
        raise ImportError("recording needs h5py: pip install 'ikaros[record]'")
    monkeypatch.setattr(recording, "h5py_module", missing)
    data = tmp_path / "data" / "recordings"
    net = load_body(tmp_path, BODY, user_data=str(data))
    with TestClient(create_app(net)) as client:
        r = client.post("/api/record", json={"on": True})
        assert r.status_code == 501 and "pip install" in r.json()["error"]
    net.close()
    assert not os.path.exists(data)
    existing = tmp_path / "existing"
    existing.mkdir()                     # a folder that was there stays
    net = load_body(tmp_path, BODY, user_data=str(existing))
    with TestClient(create_app(net)) as client:
        assert client.post("/api/record", json={"on": True}).status_code == 501
    net.close()
    assert os.path.isdir(existing)
