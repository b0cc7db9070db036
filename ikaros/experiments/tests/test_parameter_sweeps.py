"""Parameter sweeps: grids, local processes, single runs, failures, the CLI, and Ray."""
import os
import time

import numpy as np
import pytest

pd = pytest.importorskip("pandas")
pytest.importorskip("h5py")
pytest.importorskip("xarray")

from ikaros.cli import main  # noqa: E402
from ikaros.experiments import open_recording  # noqa: E402
from ikaros.experiments.sweeps import RunSpec, grid, parse_values, run_one, sweep  # noqa: E402

# Counter.OUTPUT is step * (k + 1) on tick k; Double.OUTPUT is factor times that. Boom
# raises in tick 3 when fail is 1, and ends its process there when fail is 2.
MODEL = """<group name="Sweep" factor="2">
<module class="Sweep" name="Counter" min="0" max="1e9" step="1"/>
<module class="Scale" name="Double" factor="@factor"/>
<module class="Boom" name="Boom" fail="0"/>
<connection source="Counter.OUTPUT" target="Double.INPUT" delay="0"/>
</group>
"""
BOOM = '''import os
from ikaros import Module, Parameter


class Boom(Module):
    """Fails on tick 3: raises (fail=1) or ends its process (fail=2)."""
    fail = Parameter(0, "how to fail", type="int")

    def tick(self):
        if self.clock.tick == 3 and self.fail == 1:
            raise RuntimeError("boom")
        if self.clock.tick == 3 and self.fail == 2:
            os._exit(3)
'''


@pytest.fixture
def model(tmp_path):
    (tmp_path / "Boom.py").write_text(BOOM)
    path = tmp_path / "sweep.ikg"
    path.write_text(MODEL)
    return str(path)


def test_values_of_a_setting():
    assert parse_values("0.05:0.5:0.05") == [0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4,
                                             0.45, 0.5]
    assert parse_values("1:20") == list(range(1, 21))
    assert parse_values("0:10:5") == [0, 5, 10]
    assert parse_values("1,2.5,yes") == [1, 2.5, "yes"]
    assert parse_values("7") == [7]
    for bad in ("1:", "1:2:0", "2:1", "a:b", "1,,2"):
        with pytest.raises(ValueError):
            parse_values(bad)
    assert grid({"a": [1, 2], "b": [3, 4]}) == [{"a": 1, "b": 3}, {"a": 1, "b": 4},
                                               {"a": 2, "b": 3}, {"a": 2, "b": 4}]


def single_runs(model, settings, ticks):
    text = open(model).read()
    return [run_one(RunSpec(k, model, text, combo, ticks, ["Double.OUTPUT"]))
            for k, combo in enumerate(grid(settings))]


def test_two_local_workers_give_the_table_of_single_runs(model):
    settings = {"factor": [1, 3], "Counter.step": [0.5, 2]}
    table = sweep(model, settings, 40, record="Double.OUTPUT", workers=2, progress=False)
    assert list(table["run"]) == [0, 1, 2, 3]
    assert list(table["status"]) == ["ok"] * 4
    assert list(table["ticks"]) == [40] * 4
    # Double = factor * step * 40 (the ramp's 40th step), exactly in float32
    assert list(table["Double.OUTPUT"]) == [20.0, 80.0, 60.0, 240.0]
    singles = pd.DataFrame(single_runs(model, settings, 40))
    same = ["run", "factor", "Counter.step", "status", "error", "ticks", "Double.OUTPUT"]
    pd.testing.assert_frame_equal(table[same], singles[same])


def test_a_run_that_raises_is_reported_and_the_others_finish(model):
    failures = []
    table = sweep(model, {"Boom.fail": [0, 1, 0]}, 10, record="Double.OUTPUT", workers=2,
                  retries=1, progress=False, on_failure=failures.append)
    assert list(table["status"]) == ["ok", "error", "ok"]
    assert list(table["attempts"]) == [1, 2, 1]
    assert table["error"][1].startswith("RunError: ") and "boom" in table["error"][1]
    assert list(table["Double.OUTPUT"][[0, 2]]) == [20.0, 20.0]
    assert list(table["ticks"]) == [10, 4, 10]      # ticks 0-3 ran; tick 3 failed
    assert len(failures) == 1 and failures[0]["Boom.fail"] == 1
    import ikaros
    assert ikaros.sweep is sweep


def test_a_worker_process_that_dies_fails_only_its_run(model):
    table = sweep(model, {"Boom.fail": [0, 2, 0, 0]}, 10, record="Double.OUTPUT",
                  workers=2, retries=0, progress=False, on_failure=lambda row: None)
    assert table["status"][1] == "error"
    assert "worker process died" in table["error"][1]
    assert list(table["status"]) == ["ok", "error", "ok", "ok"]


def test_the_command_line_writes_a_table_and_one_recording_per_run(model, tmp_path, capsys):
    out = tmp_path / "out"
    status = main(["sweep", model, "--set", "factor=1:2", "--set", "Boom.fail=0,1",
                   "--ticks", "20", "--record", "Double.*", "--out", str(out),
                   "--format", "csv", "--workers", "2", "--retries", "0"])
    assert status == 1                        # one run failed, the others ran
    err = capsys.readouterr().err
    assert "run 1 (factor=1, Boom.fail=1) failed after 1 attempt(s): RunError" in err
    assert "4 runs, 2 ok, 2 failed" in err
    table = pd.read_csv(out / "results.csv")
    assert list(table["status"]) == ["ok", "error", "ok", "error"]
    assert list(table["Double.OUTPUT"][[0, 2]]) == [20.0, 40.0]
    recorded = open_recording(str(out / "run_2.h5"))
    assert table["recording"][2] == str(out / "run_2.h5")
    np.testing.assert_array_equal(recorded["Double.OUTPUT"].values[:, 0],
                                  2 * np.arange(1, 21))
    assert recorded.attrs["finished"] is True
    assert sorted(os.listdir(out)) == ["results.csv", "run_0.h5", "run_1.h5", "run_2.h5",
                                       "run_3.h5", "sweep.json"]


def test_command_line_usage_errors(model, capsys):
    with pytest.raises(SystemExit) as e:
        main(["sweep", model, "--set", "factor=2:1", "--ticks", "5"])
    assert e.value.code == 2
    assert "--set factor:" in capsys.readouterr().err
    assert main(["sweep", "missing.ikg", "--ticks", "5", "--workers", "1"]) == 1
    capsys.readouterr()
    assert main(["sweep", model, "--ticks", "5", "--workers", "2", "--record", "Nothing.*"]) == 1
    assert "ikaros sweep: error: no output matches 'Nothing.*'" in capsys.readouterr().err


def test_a_local_ray_instance_gives_the_same_table(model):
    """Starts a local Ray instance of two CPUs (10-16 s here, most of it Ray's start)."""
    ray = pytest.importorskip("ray")
    settings = {"factor": [1, 3], "Boom.fail": [0, 1]}
    started = time.monotonic()
    table = sweep(model, settings, 30, record="Double.OUTPUT", backend="ray", workers=2,
                  retries=0, progress=False, on_failure=lambda row: None)
    assert time.monotonic() - started < 120
    assert not ray.is_initialized()           # the instance it started is shut down
    local = sweep(model, settings, 30, record="Double.OUTPUT", workers=2, retries=0,
                  progress=False, on_failure=lambda row: None)
    same = ["run", "factor", "Boom.fail", "status", "ticks", "Double.OUTPUT"]
    pd.testing.assert_frame_equal(table[same], local[same])
    assert list(table["status"]) == ["ok", "error", "ok", "error"]
    assert list(table["Double.OUTPUT"][[0, 2]]) == [30.0, 90.0]


def test_a_parameter_the_module_does_not_have_fails_the_run_with_its_name(model):
    runs = single_runs(model, {"Double.nope": [1], "Counter.step": [1]}, 5)
    assert [r["status"] for r in runs] == ["error"]
    assert runs[0]["error"].startswith('KeyError: \'no parameter "Double.nope" in Sweep\'')
