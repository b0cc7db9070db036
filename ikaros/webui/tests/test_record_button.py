"""The record button in the browser: pressed, the running model is recorded into an HDF5
file in the models folder; pressed again, the recording ends."""
import os
import time

import numpy as np
import pytest

pytest.importorskip("h5py")
pytest.importorskip("xarray")

from browsing import in_own_browser  # noqa: E402

import ikaros  # noqa: E402
from ikaros.experiments import open_recording  # noqa: E402

MODEL = '<group name="R"><module class="Sweep" name="Counter" step="1" max="1e9"/></group>\n'


def test_the_record_button_records_into_the_models_folder(tmp_path):
    path = tmp_path / "counter.ikg"
    path.write_text(MODEL)

    def open_page(server, page):
        page.wait_for_selector("#run-record")

    def check(server, page):
        button = page.locator("#run-record")
        assert button.inner_text() == "● Record"
        button.click()
        page.wait_for_selector("#run-record.active")
        assert button.inner_text() == "● Recording"
        server.post("/api/control", {"state": "play"})
        deadline = time.monotonic() + 10
        while server.get("/api/status")["tick"] < 200 and time.monotonic() < deadline:
            time.sleep(0.05)
        button.click()
        page.wait_for_selector("#run-record:not(.active)")
        assert page.locator(".message", has_text="recording into counter-").count() == 1
        assert not page.errors

    in_own_browser(str(path), open_page, check)
    files = [f for f in os.listdir(tmp_path) if f.endswith(".h5")]
    assert len(files) == 1 and files[0].startswith("counter-")
    ds = open_recording(str(tmp_path / files[0]))
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
