"""The web UI's record button endpoint: /api/record starts and ends a recording in the
user-data folder (ikaros -u)."""
import os
import warnings

import numpy as np
import pytest

pytest.importorskip("h5py")
pytest.importorskip("xarray")
pytest.importorskip("starlette")
warnings.filterwarnings("ignore", message=".*httpx.*")

from starlette.testclient import TestClient  # noqa: E402

from ikaros.experiments import open_recording  # noqa: E402
from ikaros.testing import load_body  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")


def test_record_on_and_off(tmp_path):
    models = tmp_path / "models"
    models.mkdir()
    net = load_body(tmp_path, '<module class="Sweep" name="Counter" step="1" max="1e9"/>',
                    user_data=str(models))
    with TestClient(create_app(net, models_dir=str(models))) as client:
        assert client.get("/api/record").json() == {
            "recording": False, "file": None, "folder": str(models), "outputs": 1,
            "values": 1, "largest": [["Counter.OUTPUT", 1]]}
        net.run(ticks=5)
        state = client.post("/api/record", json={"on": True}).json()
        assert state["recording"] is True
        assert state["file"].startswith("model-") and state["file"].endswith(".h5")
        net.run(ticks=20)
        assert client.get("/api/record").json()["recording"] is True
        assert client.post("/api/record", json={"on": False}).json()["recording"] is False
        net.run(ticks=3)
        assert client.post("/api/record", json={"on": "yes"}).status_code == 400
        assert client.post("/api/record", json={}).status_code == 400
        assert "/api/record" in client.get("/api/openapi.json").json()["paths"]
    net.close()
    ds = open_recording(str(models / state["file"]))
    np.testing.assert_array_equal(ds["tick"].values, np.arange(5, 25))
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], np.arange(6, 26))
    assert ds.attrs["finished"] is True
    assert os.listdir(models) == [state["file"]]


def test_a_second_recording_never_overwrites_the_first(tmp_path):
    net = load_body(tmp_path, '<module class="Sweep" name="Counter" step="1" max="1e9"/>',
                    user_data=str(tmp_path))
    with TestClient(create_app(net, models_dir=str(tmp_path))) as client:
        first = client.post("/api/record", json={"on": True}).json()["file"]
        second = client.post("/api/record", json={"on": True}).json()["file"]
        client.post("/api/record", json={"on": False})
    net.close()
    assert first != second
    assert {first, second} <= set(os.listdir(tmp_path))


def test_the_replay_bar_shows_any_recorded_row(tmp_path):
    from ikaros.experiments.replay import replay_network
    net = load_body(tmp_path, '<module class="Sweep" name="Counter" step="1" max="1e9"/>')
    with net.record(str(tmp_path / "run.h5"), every=2):
        net.run(ticks=40)
    net.close()
    replayed = replay_network(str(tmp_path / "run.h5"))
    with TestClient(create_app(replayed)) as client:
        assert client.get("/api/replay").json() == {"replay": True, "file": "run.h5",
                                                    "rows": 20, "row": -1, "tick": None}
        state = client.post("/api/replay", json={"row": 7}).json()
        assert state == {"replay": True, "file": "run.h5", "rows": 20, "row": 7, "tick": 14}
        assert replayed.output("Counter.OUTPUT")[0] == 15       # recorded on tick 14
        assert client.post("/api/replay", json={"row": 20}).status_code == 400
        assert client.post("/api/replay", json={"row": True}).status_code == 400
    replayed.close()
    plain = load_body(tmp_path, '<module class="Sweep" name="Counter"/>')
    with TestClient(create_app(plain)) as client:
        assert client.get("/api/replay").json() == {"replay": False}
        assert client.post("/api/replay", json={"row": 0}).status_code == 409
    plain.close()


def test_replay_on_the_command_line_needs_no_model_and_no_batch(tmp_path, capsys):
    from ikaros.cli import main
    with pytest.raises(SystemExit) as e:
        main(["-b", "--replay", str(tmp_path / "run.h5")])
    assert e.value.code == 2
    assert "--replay shows a recording in the web UI" in capsys.readouterr().err
    (tmp_path / "bad.h5").write_bytes(b"no")
    assert main(["--replay", str(tmp_path / "bad.h5")]) == 1
    assert "ikaros: error: --replay: cannot read the recording" in capsys.readouterr().err


def test_an_apply_ends_the_recording_of_the_network_it_replaces(tmp_path):
    net = load_body(tmp_path, '<module class="Sweep" name="Counter" step="1" max="1e9"/>',
                    user_data=str(tmp_path))
    app = create_app(net, models_dir=str(tmp_path))
    with TestClient(app) as client:
        file = client.post("/api/record", json={"on": True}).json()["file"]
        net.run(ticks=10)
        tree = client.get("/api/model").json()["tree"]
        assert client.post("/api/apply", json={"tree": tree}).status_code == 200
        assert client.get("/api/record").json()["recording"] is False
        new = app.state.ui.net
        assert new is not net
        new.run(ticks=5)                  # the ended recording keeps nothing
        again = client.post("/api/record", json={"on": True}).json()
        assert again["recording"] is True
        assert len(new._taps) == 1        # only the new recording's tap
        client.post("/api/record", json={"on": False})
    new.close()
    ds = open_recording(str(tmp_path / file))
    assert ds.attrs["finished"] is True
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], np.arange(1, 11))


def test_a_recording_whose_disk_fills_ends_at_once_and_its_empty_file_goes(tmp_path,
                                                                          monkeypatch):
    import errno
    from ikaros.errors import RunError
    from ikaros.experiments import recording
    from ikaros.testing import wait_for

    def full(*args):                       # the writer thread's writes fail, as on a full disk
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(recording, "shuffled_deflate", full)
    net = load_body(tmp_path, '<module class="Sweep" name="Counter" step="1" max="1e9"/>',
                    user_data=str(tmp_path))
    net.log_level = -1
    try:
        with TestClient(create_app(net, models_dir=str(tmp_path))) as client:
            file = client.post("/api/record", json={"on": True}).json()["file"]
            assert (tmp_path / file).exists()

            def run():
                if not net.stopped:
                    try:
                        net.run(ticks=5)
                    except RunError:        # the run stops (on_error="stop")
                        pass
                return net.stopped
            def recording_ended():          # the writer writes a second after the start
                if client.get("/api/record").json()["recording"] is False:
                    return True
                run()
                return False
            assert wait_for(recording_ended, 60, 0.02)
            assert not (tmp_path / file).exists()      # now, not when the server quits
            assert wait_for(run, 60, 0.02)             # the failure is told at a tick
            assert [m for _, _, _, m in net.log if "No space" in m] == [
                f"writing the recording {tmp_path / file} failed (No space left on "
                f"device); it holds no ticks (the file is removed); the run stops"]
    finally:
        net.close()
