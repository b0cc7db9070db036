"""Recording with the compiled tick (its output tap copies the rows in the compiled call)
gives the same file as recording with the NumPy kernel, tick by tick."""
import time

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")
pytest.importorskip("xarray")
pytest.importorskip("numba", reason="the compiled tick needs numba (pip install ikaros[fast])")

from ikaros.experiments import open_recording, recording  # noqa: E402
from ikaros.testing import load_body  # noqa: E402

# a Python source, compiled modules behind delay-1 connections (so the compiled tick has its
# gather call, where the tap's copy runs), a zero-delay one and an integrator with state
BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Sweep" name="Grid" outputsize_x="3" outputsize_y="2" min="0" max="100000000"
        step="0.5"/>
<module class="Scale" name="Double" factor="2"/>
<module class="Add" name="Sum"/>
<module class="Integrator" name="Acc" alpha="0.5" beta="1"/>
<connection source="Counter.OUTPUT" target="Double.INPUT"/>
<connection source="Double.OUTPUT" target="Sum.INPUT1"/>
<connection source="Counter.OUTPUT" target="Sum.INPUT2" delay="0"/>
<connection source="Grid.OUTPUT" target="Acc.INPUT"/>
"""
DATASETS = ("data", "tick", "time", "real_time")


def record(folder, compiled: str, steps: int, ticks: int, **options):
    """Record (``steps`` single steps, then a run of ``ticks``) and return the file's
    datasets, the outputs seen after every step, and whether the tap was compiled."""
    net = load_body(folder, BODY, compiled=compiled)
    recorder = net.record(str(folder / "run.h5"), **options)
    seen = []
    for _ in range(steps):
        net.step()
        seen.append(np.concatenate([net.output(s.name).ravel() for s in recorder.signals]))
    tapped = recorder._tap.compiled
    net.run(ticks=ticks)
    recorder.close()
    net.close()
    with h5py.File(folder / "run.h5", "r") as f:
        return {name: f[name][()] for name in DATASETS}, np.array(seen), tapped


@pytest.mark.parametrize("options", [{}, {"every": 3}, {"only": ["Sum.*", "Acc.*"]}],
                         ids=["all", "every 3", "only"])
def test_the_compiled_tick_records_the_same_file(tmp_path, monkeypatch, options):
    # small chunks and blocks: the ring of blocks is filled and reused many times over,
    # and a partly filled block is handed over after every tick
    monkeypatch.setattr(recording, "CHUNK_BYTES", 64)
    monkeypatch.setattr(recording, "BLOCK_BYTES", 300)
    monkeypatch.setattr(recording, "FLUSH_SECONDS", 0.0)
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    plain, seen, tapped = record(tmp_path / "a", "no", 30, 400, **options)
    assert not tapped
    fast, seen_fast, tapped = record(tmp_path / "b", "yes", 30, 400, **options)
    assert tapped
    every = options.get("every", 1)
    np.testing.assert_array_equal(plain["tick"], np.arange(0, 430, every))
    for name in ("data", "tick", "time"):
        np.testing.assert_array_equal(fast[name], plain[name])
    for real_time in (plain["real_time"], fast["real_time"]):     # from the first row's tick
        assert real_time[0] == 0 and np.all(np.diff(real_time) >= 0)
    np.testing.assert_array_equal(seen_fast, seen)
    np.testing.assert_array_equal(plain["data"][:-(-30 // every)], seen[::every])


def test_the_row_of_the_last_tick_is_kept_when_the_recording_ends(tmp_path):
    net = load_body(tmp_path, BODY, compiled="yes")
    recorder = net.record(str(tmp_path / "run.h5"), only="Sum.OUTPUT")
    assert recorder._tap.compiled
    net.run(ticks=7)             # the 7th tick's row is copied by close(), not by a tick
    recorder.close()
    net.run(ticks=3)             # and the tap is gone: these are not recorded
    net.close()
    ds = open_recording(str(tmp_path / "run.h5"))
    k = np.arange(7, dtype=np.float32)
    np.testing.assert_array_equal(ds["tick"].values, np.arange(7))
    # Counter is k + 1 on tick k, Double 2 k (one tick late), Sum Double one tick late
    # plus Counter
    np.testing.assert_array_equal(ds["Sum.OUTPUT"].values[:, 0],
                                  2 * np.maximum(k - 1, 0) + (k + 1))


def test_the_compiled_tick_calls_the_recorder_only_when_a_block_is_full(tmp_path, monkeypatch):
    # 15 values a row, 5 rows a block: the compiled call keeps rows and tick numbers by
    # itself and calls the recorder back once per block (no flush asked for in 60 s)
    monkeypatch.setattr(recording, "CHUNK_BYTES", 64)
    monkeypatch.setattr(recording, "BLOCK_BYTES", 300)
    calls = []
    signalled = recording.Recorder._signalled
    monkeypatch.setattr(recording.Recorder, "_signalled",
                        lambda self: (calls.append(self.net.tick), signalled(self)))
    net = load_body(tmp_path, BODY, compiled="yes")
    recorder = recording.Recorder(net, str(tmp_path / "run.h5"), every=2,
                                  flush_seconds=60)
    assert recorder._tap.compiled and recorder._block_rows == 5
    net.run(ticks=101)          # ticks 0 to 100; the 51st row (tick 100) taken at the close
    recorder.close()
    # the 5th row of a block (tick 8, 18, ...) is kept when the next tick starts
    assert calls == list(range(9, 100, 10))
    net.close()
    with h5py.File(tmp_path / "run.h5", "r") as f:
        np.testing.assert_array_equal(f["tick"][()], np.arange(0, 101, 2))
        np.testing.assert_array_equal(f["time"][()], np.arange(0, 101, 2) * 0.01)
        np.testing.assert_array_equal(f["data"][:, 0], np.arange(1, 102, 2))   # Counter


def test_the_writer_asks_for_the_rows_of_a_partly_filled_block_while_running(tmp_path):
    # one block holds the whole run: its rows reach the file only when the writer asks
    # for them (every flush_seconds), while the network runs
    net = load_body(tmp_path, BODY, compiled="yes")
    path = tmp_path / "run.h5"
    recorder = recording.Recorder(net, str(path), only="Counter.OUTPUT", flush_seconds=0.05)
    assert recorder._tap.compiled and recorder._block_rows > 10000
    deadline = time.monotonic() + 30
    rows = 0
    while rows == 0:
        assert time.monotonic() < deadline, "no rows in the file after 30 s"
        net.run(ticks=10)
        time.sleep(0.02)
        with h5py.File(path, "r", swmr=True) as f:
            rows = f["tick"].shape[0]
            ticks, data = f["tick"][()], f["data"][:rows, 0]
    np.testing.assert_array_equal(ticks, np.arange(rows))
    np.testing.assert_array_equal(data, np.arange(1, rows + 1))
    recorder.close()
    net.close()
