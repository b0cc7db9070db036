"""The record button in the browser: pressed, the running model is recorded into an HDF5
file in the user-data folder (never the models folder); pressed again, the recording ends."""
import os
import time

import numpy as np
import pytest

pytest.importorskip("h5py")
pytest.importorskip("xarray")

from browsing import ARTIFACTS, in_own_browser  # noqa: E402

import ikaros  # noqa: E402
from ikaros.experiments import open_recording  # noqa: E402

MODEL = '<group name="R"><module class="Sweep" name="Counter" step="1" max="1e9"/></group>\n'


def test_the_record_button_records_into_the_user_data_folder(tmp_path):
    """Issue 27, item 5: with ``-u DIR`` the recording goes into DIR, and the page names the
    folder and the file; nothing is written beside the model."""
    path = tmp_path / "counter.ikg"
    path.write_text(MODEL)
    data = tmp_path / "data"

    def open_page(server, page):
        page.wait_for_selector("#run-record")

    def check(server, page):
        button = page.locator("#run-record")
        assert button.inner_text() == "● Record"
        button.click()
        page.wait_for_selector("#record-amount:has-text('1 output, 1 values')")
        page.click("#record-start")
        page.wait_for_selector("#run-record.active")
        assert button.inner_text().startswith("● Recording")
        server.post("/api/control", {"state": "play"})
        deadline = time.monotonic() + 10
        while server.get("/api/status")["tick"] < 200 and time.monotonic() < deadline:
            time.sleep(0.05)
        button.click()
        page.wait_for_selector("#run-record:not(.active)")
        assert page.locator(".message", has_text=f"recording into {data}/counter-").count() == 1
        assert page.locator(".message", has_text=f"recording ended: {data}/counter-").count() == 1
        assert not page.errors

    in_own_browser(str(path), open_page, check, options=["-u", str(data)])
    assert not [f for f in os.listdir(tmp_path) if f.endswith(".h5")]
    files = [f for f in os.listdir(data) if f.endswith(".h5")]
    assert len(files) == 1 and files[0].startswith("counter-")
    ds = open_recording(str(data / files[0]))
    assert ds.attrs["finished"] is True and ds.sizes["tick"] >= 100
    ticks = ds["tick"].values
    np.testing.assert_array_equal(ticks, np.arange(ticks[0], ticks[0] + len(ticks)))
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], ticks + 1)


def test_replay_scrubs_through_a_recording_in_its_views(tmp_path):
    path = tmp_path / "counter.ikg"
    path.write_text('<group name="R"><module class="Sweep" name="Counter" step="1" '
                    'max="1e9"/><view name="V"><table source="Counter.OUTPUT" '
                    'title="Count"/></view></group>\n')
    net = ikaros.load(str(path))
    with net.record(str(tmp_path / "run.h5")):
        net.run(ticks=300)
    net.close()

    def open_page(server, page):
        page.wait_for_selector("#replay-slider")

    def check(server, page):
        assert page.locator("#run-record").count() == 0
        page.locator("#replay-slider").fill("120")
        page.wait_for_function("() => document.querySelector('#replay-tick').textContent"
                               ".includes('recorded tick 120 (row 121/300)')")
        assert server.get("/api/replay")["row"] == 120
        assert server.data("Counter.OUTPUT")["data"]["Counter.OUTPUT"] == [121]
        page.locator(".widget-table", has_text="121").wait_for()
        assert not page.errors

    in_own_browser(str(tmp_path / "run.h5"), open_page, check, options=["--replay"])


def test_without_user_data_recordings_go_to_the_users_data_folder(tmp_path, monkeypatch):
    """Issue 27, item 5: with no ``-u``, the record button writes into ``recordings`` in the
    user's data folder (``$XDG_DATA_HOME/ikaros/recordings``), not beside the model."""
    from starlette.testclient import TestClient
    from ikaros.webui.server import create_app
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "xdg"))
    models = tmp_path / "models"
    models.mkdir()
    (models / "counter.ikg").write_text(MODEL)
    net = ikaros.load(str(models / "counter.ikg"))
    folder = tmp_path / "xdg" / "ikaros" / "recordings"
    try:
        with TestClient(create_app(net)) as client:
            assert client.get("/api/record").json() == {
                "recording": False, "file": None, "folder": str(folder), "outputs": 1,
                "values": 1, "largest": [["Counter.OUTPUT", 1]]}
            started = client.post("/api/record", json={"on": True}).json()
            assert started["recording"] and started["folder"] == str(folder)
            assert started["file"].startswith("counter-") and started["file"].endswith(".h5")
            net.step()
            assert client.post("/api/record", json={"on": False}).json()["recording"] is False
    finally:
        net.close()
    assert os.listdir(models) == ["counter.ikg"]
    assert os.listdir(folder) == [started["file"]]


def test_the_record_dialog_says_how_much_it_writes_and_records_what_is_chosen(tmp_path):
    """Issue 37, item 8: the demo recorded every output, about 20 MB a second, and nothing
    said so. The dialog of the record button says how many values a tick and megabytes a
    second a recording writes (4 bytes a value, at the present tick rate), and records only
    the outputs that match what the user types, every n-th tick."""
    data = tmp_path / "data"
    demo = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))), "examples", "demo.ikg")
    everything = {}

    def check(server, page):
        everything.update(server.get("/api/record"))
        server.post("/api/control", {"state": "realtime"})
        page.wait_for_function("() => window.ikaros.status.ticks_per_second > 0")
        page.click("#run-record")
        n = everything["values"]
        note = page.locator("#record-amount")
        page.wait_for_selector(f"#record-amount:has-text('{n} values')")
        assert "a second" in note.inner_text() and "Picture.OUTPUT" in note.inner_text()
        page.screenshot(path=os.path.join(ARTIFACTS, "record-dialog.png"))
        page.fill("#record-only", "Gain.OUTPUT, Sine.*")
        page.wait_for_selector("#record-amount:has-text('2 outputs, 9 values: 36 bytes a recorded tick')")
        page.fill("#record-only", "Nothing.*")
        page.wait_for_selector("#record-amount.error:has-text('no output matches')")
        page.fill("#record-only", "Gain.OUTPUT, Sine.*")
        page.fill("#record-every", "2")
        page.click("#record-start")
        page.wait_for_selector("#run-record.active")
        page.wait_for_function("() => /● Recording [0-9.]+ (bytes|kB)\\/s/.test("
                               "document.querySelector('#run-record').textContent)")
        tick = server.tick()
        deadline = time.monotonic() + 20
        while server.tick() < tick + 30 and time.monotonic() < deadline:
            time.sleep(0.05)
        page.click("#run-record")
        page.wait_for_selector("#run-record:not(.active)")
        assert not page.errors, page.errors

    in_own_browser(demo, lambda s, p: None, check, options=["-u", str(data)])
    assert everything["values"] > 10000
    (name,) = [f for f in os.listdir(data) if f.endswith(".h5")]
    ds = open_recording(str(data / name))
    assert sorted(v for v in ds.data_vars if v.endswith("OUTPUT")) == ["Gain.OUTPUT", "Sine.OUTPUT"]
    ticks = ds["tick"].values
    assert len(ticks) >= 10 and set(np.diff(ticks)) == {2}
