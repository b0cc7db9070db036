"""Recording a run into HDF5 and reading it back (Python API, CLI, a run killed mid-way)."""
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")
pytest.importorskip("xarray")

import ikaros  # noqa: E402
from ikaros.cli import main  # noqa: E402
from ikaros.experiments import open_recording  # noqa: E402
from ikaros.testing import load_body  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))

# Counter.OUTPUT is k + 1 on tick k; Double.OUTPUT 2 (k + 1); Grid.OUTPUT a 2x3 matrix of
# (k + 1) / 2 (steps of 0.5)
BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Scale" name="Double" factor="2"/>
<module class="Sweep" name="Grid" outputsize_x="3" outputsize_y="2" min="0" max="100000000"
        step="0.5"/>
<connection source="Counter.OUTPUT" target="Double.INPUT" delay="0"/>
"""


def model(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">{BODY}</group>\n')
    return str(path)


def test_a_recording_read_back_equals_the_outputs_tick_by_tick(tmp_path):
    net = load_body(tmp_path, BODY)
    recorder = net.record(str(tmp_path / "run.h5"))
    seen = {"Counter.OUTPUT": [], "Double.OUTPUT": [], "Grid.OUTPUT": []}
    for _ in range(50):
        net.step()
        for name in seen:
            seen[name].append(net.output(name))
    net.run(ticks=250)           # the controller's loop records too
    recorder.close()
    net.close()
    ds = open_recording(str(tmp_path / "run.h5"))
    assert list(ds.data_vars) == ["Counter.OUTPUT", "Double.OUTPUT", "Grid.OUTPUT"]
    assert ds.sizes["tick"] == 300
    np.testing.assert_array_equal(ds["tick"].values, np.arange(300))
    np.testing.assert_allclose(ds["time"].values, np.arange(300) * 0.01)
    for name, values in seen.items():
        np.testing.assert_array_equal(ds[name].values[:50], np.array(values))
    k = np.arange(300, dtype=np.float32)
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], k + 1)
    np.testing.assert_array_equal(ds["Double.OUTPUT"].values[:, 0], 2 * (k + 1))
    assert ds["Grid.OUTPUT"].dims == ("tick", "Grid.OUTPUT.dim_0", "Grid.OUTPUT.dim_1")
    np.testing.assert_array_equal(ds["Grid.OUTPUT"].values,
                                  np.broadcast_to(((k + 1) / 2)[:, None, None], (300, 2, 3)))
    assert np.all(np.diff(ds["real_time"].values) >= 0)
    assert ds.attrs["finished"] is True
    assert ds.attrs["top_group"] == "Test"
    assert 'name="Counter"' in ds.attrs["model"]
    assert ds.attrs["parameters"]["Double.factor"] == "2"
    assert ds.attrs["seeds"] == {}
    assert ds.attrs["ikaros_version"] == ikaros.__version__


def test_only_every_and_parameter_changes(tmp_path):
    net = load_body(tmp_path, BODY)
    with net.record(str(tmp_path / "run.h5"), only=["D*.OUTPUT", "Counter.*"], every=3):
        net.run(ticks=10)
        net.set_parameter("Double.factor", 5)
        net.run(ticks=10)
    net.close()
    ds = open_recording(str(tmp_path / "run.h5"))
    assert list(ds.data_vars) == ["Counter.OUTPUT", "Double.OUTPUT"]
    ticks = np.arange(0, 20, 3)
    np.testing.assert_array_equal(ds["tick"].values, ticks)
    factor = np.where(ticks < 10, 2, 5)
    np.testing.assert_array_equal(ds["Double.OUTPUT"].values[:, 0], factor * (ticks + 1))
    assert ds.attrs["parameter_changes"] == [(10, "Double.factor", "5")]
    assert ds.attrs["every"] == 3
    only = open_recording(str(tmp_path / "run.h5"), only="Double.*")
    assert list(only.data_vars) == ["Double.OUTPUT"]


def test_the_seeds_are_kept(tmp_path):
    net = load_body(tmp_path, '<module class="Randomizer" name="Noise" seed="3"/>')
    with net.record(str(tmp_path / "run.h5")):
        net.run(ticks=2)
    net.close()
    assert open_recording(str(tmp_path / "run.h5")).attrs["seeds"] == {"Noise.seed": "3"}


def test_a_pattern_that_matches_nothing_is_an_error(tmp_path):
    net = load_body(tmp_path, BODY)
    with pytest.raises(ValueError, match="no output matches 'Arm.\\*'"):
        net.record(str(tmp_path / "run.h5"), only="Arm.*")
    net.close()


def test_net_close_ends_the_recording(tmp_path):
    net = load_body(tmp_path, BODY)
    net.record(str(tmp_path / "run.h5"), only="Counter.OUTPUT")
    net.run(ticks=7)
    net.close()
    ds = open_recording(str(tmp_path / "run.h5"))
    assert ds.attrs["finished"] is True
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], np.arange(1, 8))


def test_run_with_record_returns_the_signals_in_memory(tmp_path):
    net = load_body(tmp_path, BODY)
    net.run(ticks=4)
    ds = net.run(ticks=10, record=["Double.OUTPUT"], every=2)
    assert net.tick == 14
    np.testing.assert_array_equal(ds["tick"].values, [4, 6, 8, 10, 12])
    np.testing.assert_array_equal(ds["Double.OUTPUT"].values[:, 0], [10, 14, 18, 22, 26])
    everything = net.run(ticks=2, record="*")
    assert list(everything.data_vars) == ["Counter.OUTPUT", "Double.OUTPUT", "Grid.OUTPUT"]
    net.close()


def test_the_command_line_records(tmp_path):
    out = tmp_path / "run.h5"
    assert main(["-b", "-q", "-s", "40", model(tmp_path), "--record", str(out),
                 "--record-only", "Counter.*", "--record-every", "4"]) == 0
    ds = open_recording(str(out))
    np.testing.assert_array_equal(ds["tick"].values, np.arange(0, 40, 4))
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], np.arange(1, 41, 4))
    assert ds.attrs["command_line"][:4] == ["ikaros", "-b", "-q", "-s"]


def test_command_line_errors(tmp_path, capsys):
    assert main(["-b", "-s", "4", model(tmp_path), "--record", str(tmp_path / "a.h5"),
                 "--record-only", "Nothing.*"]) == 1
    assert "ikaros: error: --record: no output matches 'Nothing.*'" in capsys.readouterr().err
    assert main(["-b", "-s", "4", model(tmp_path), "--record",
                 str(tmp_path / "missing" / "a.h5")]) == 1
    assert "cannot write the recording" in capsys.readouterr().err
    with pytest.raises(SystemExit) as e:
        main(["-b", "-s", "4", model(tmp_path), "--record-every", "2"])
    assert e.value.code == 2


READER = """import sys
import h5py
with h5py.File(sys.argv[1], "r", swmr=True):
    print("open", flush=True)
    sys.stdin.readline()
"""


def test_a_recording_read_while_it_closes_is_marked_finished(tmp_path):
    """A reader in another process (SWMR) that has the file open as the recording ends
    does not keep it from being marked finished."""
    net = load_body(tmp_path, BODY)
    recorder = net.record(str(tmp_path / "run.h5"))
    net.run(ticks=100)
    reader = subprocess.Popen([sys.executable, "-c", READER, str(tmp_path / "run.h5")],
                              stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert reader.stdout.readline() == "open\n"
        recorder.close()
        assert recorder.failure is None
    finally:
        reader.communicate("\n", timeout=30)
    net.close()
    with h5py.File(tmp_path / "run.h5", "r") as f:
        assert bool(f.attrs["finished"]) is True
        assert f.attrs["ticks_recorded"] == 100


def test_a_run_killed_mid_way_is_readable_up_to_its_last_flushed_chunk(tmp_path):
    out = tmp_path / "run.h5"
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-q", "-s", "1000000000",
                             model(tmp_path), "--record", str(out)], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        deadline = time.monotonic() + 60
        rows = 0
        while rows < 20000:        # read while it runs (SWMR)
            assert time.monotonic() < deadline, "the recording did not grow in 60 s"
            assert proc.poll() is None, proc.stderr.read().decode()
            time.sleep(0.2)
            if out.exists():
                try:
                    rows = open_recording(str(out)).sizes["tick"]
                except OSError:
                    rows = 0       # not yet past its first flush
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
    ds = open_recording(str(out))
    n = ds.sizes["tick"]
    assert n >= 20000
    assert ds.attrs["finished"] is False
    np.testing.assert_array_equal(ds["tick"].values, np.arange(n))
    k = np.arange(n, dtype=np.float32)
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], k + 1)
    np.testing.assert_array_equal(ds["Double.OUTPUT"].values[:, 0], 2 * (k + 1))
    assert ds.attrs["command_line"][0] == "ikaros"
    with h5py.File(out, "r", swmr=True) as f:     # the header: JSON, with a checksum
        assert json.loads(f["header"][()].tobytes())["command_line"][0] == "ikaros"


def test_a_failing_recording_asked_to_continue_stops_with_a_warning_and_the_run_goes_on(
        tmp_path):
    net = load_body(tmp_path, BODY)
    net.log_level = -1
    recorder = net.record(str(tmp_path / "run.h5"), flush_seconds=0, on_error="continue")
    stopped = []
    net.modules["Counter"].module.stop = lambda: stopped.append(True)
    net.run(ticks=5)
    deadline = time.monotonic() + 30
    while recorder.stored < 4 and time.monotonic() < deadline:     # ticks 0-3 flushed
        time.sleep(0.01)
    recorder._fail(OSError("disk full"))       # as the writer thread reports a failure:
    net.run(ticks=5)                           # no exception: the model keeps running
    assert net.tick == 10
    net.close()
    assert stopped == [True]
    warnings = [m for _, _, _, m in net.log if "disk full" in m]
    assert warnings == [f"writing the recording {tmp_path / 'run.h5'} failed (disk full); "
                        f"it holds 4 ticks (0 to 3); the run goes on without recording"]
    ds = open_recording(str(tmp_path / "run.h5"))
    assert ds.attrs["finished"] is False
    np.testing.assert_array_equal(ds["tick"].values, np.arange(4))
