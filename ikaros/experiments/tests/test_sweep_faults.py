"""A sweep ended by SIGTERM, Ctrl-C or SIGKILL: its workers end with it, the table lists
every run with its state, interrupted recordings say so, and a second sweep into the same
folder runs only what is missing. Each sweep runs as `ikaros sweep` in a process group of
its own, so that every process of it can be looked for afterwards."""
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

pd = pytest.importorskip("pandas")
h5py = pytest.importorskip("h5py")
pytest.importorskip("xarray")

from ikaros.experiments import open_recording  # noqa: E402
from ikaros.testing import running_processes, wait_for  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))

# Slow.seconds: how long each tick sleeps while the file "gate" beside the model exists
MODEL = """<group name="Sweep">
<module class="Sweep" name="Counter" min="0" max="1e9" step="1"/>
<module class="Slow" name="Slow" seconds="0"/>
</group>
"""
SLOW = '''import os
import time
from ikaros import Module, Parameter


class Slow(Module):
    """Sleeps ``seconds`` per tick while the file "gate" beside it exists."""
    seconds = Parameter(0.0, "seconds per tick")

    def tick(self):
        if self.seconds and os.path.exists(os.path.join(os.path.dirname(__file__), "gate")):
            time.sleep(self.seconds)
'''
TICKS = 3000


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "Slow.py").write_text(SLOW)
    (tmp_path / "sweep.ikg").write_text(MODEL)
    (tmp_path / "gate").write_text("")
    return tmp_path


def start_sweep(folder):
    """`ikaros sweep` of a fast run (0) and a slow one (1: 30 s), in two workers."""
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.Popen(
        [sys.executable, "-m", "ikaros", "sweep", str(folder / "sweep.ikg"), "--set",
         "Slow.seconds=0,0.01", "--ticks", str(TICKS), "--record", "Counter.OUTPUT",
         "--out", str(folder / "out"), "--format", "csv", "--workers", "2", "-q"],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        start_new_session=True)


def finished(path) -> bool | None:
    """A recording's "finished" (None while it cannot be read)."""
    try:
        with h5py.File(path, "r", swmr=True) as f:
            return bool(f.attrs["finished"])
    except (OSError, KeyError):
        return None


def rows(path) -> int:
    try:
        return open_recording(str(path)).sizes["tick"]
    except (OSError, KeyError):
        return 0


def run_1_under_way(out):
    """Run 0 has finished and run 1 has flushed rows of its recording."""
    assert wait_for(lambda: finished(out / "run_0.h5") and rows(out / "run_1.h5") > 0,
                    120, 0.1), "run 0 finished and run 1 under way: not within 120 s"


@pytest.mark.parametrize("how", ["SIGTERM", "Ctrl-C"])
def test_an_interrupted_sweep_writes_its_table_and_leaves_no_process(folder, how):
    out = folder / "out"
    sweep = start_sweep(folder)
    try:
        run_1_under_way(out)
        signalled = time.monotonic()
        if how == "SIGTERM":
            sweep.send_signal(signal.SIGTERM)
        else:           # a terminal sends Ctrl-C to the whole process group
            os.killpg(sweep.pid, signal.SIGINT)
        _, err = sweep.communicate(timeout=30)
        assert time.monotonic() - signalled < 5
        assert sweep.returncode == 1
        assert "Traceback" not in err
        assert f"interrupted; the table of the runs so far is in {out}" in err
        assert wait_for(lambda: not running_processes(sweep.pid), 10)
    finally:
        if running_processes(sweep.pid):
            os.killpg(sweep.pid, signal.SIGKILL)
    table = pd.read_csv(out / "results.csv")
    assert list(table["run"]) == [0, 1]
    assert list(table["status"]) == ["ok", "interrupted"]
    assert table["ticks"][0] == TICKS
    ticks = int(table["ticks"][1])
    assert 0 < ticks < TICKS
    ds = open_recording(str(out / "run_1.h5"))
    assert ds.attrs["finished"] is False
    assert ds.sizes["tick"] == ticks             # every tick it ran, and nothing else
    np.testing.assert_array_equal(ds["tick"].values, np.arange(ticks))
    with h5py.File(out / "run_1.h5", "r") as f:
        assert f.attrs["ticks_recorded"] == ticks

    # a second sweep into the same folder runs only run 1
    os.remove(folder / "gate")
    done_before = os.stat(out / "run_0.h5").st_mtime_ns
    again = start_sweep(folder)
    _, err = again.communicate(timeout=120)
    assert again.returncode == 0, err
    table = pd.read_csv(out / "results.csv")
    assert list(table["status"]) == ["ok", "ok"]
    assert list(table["ticks"]) == [TICKS, TICKS]
    assert os.stat(out / "run_0.h5").st_mtime_ns == done_before
    assert open_recording(str(out / "run_1.h5")).attrs["finished"] is True


def test_a_sweep_killed_with_sigkill_leaves_no_worker(folder):
    out = folder / "out"
    sweep = start_sweep(folder)
    try:
        run_1_under_way(out)
        sweep.send_signal(signal.SIGKILL)
        sweep.wait(30)
        # the worker of run 1 hears of it (SIGTERM), closes its recording and exits
        assert wait_for(lambda: not running_processes(sweep.pid), 10)
    finally:
        if running_processes(sweep.pid):
            os.killpg(sweep.pid, signal.SIGKILL)
    ds = open_recording(str(out / "run_1.h5"))
    assert ds.attrs["finished"] is False
    n = ds.sizes["tick"]
    assert 0 < n < TICKS
    np.testing.assert_array_equal(ds["tick"].values, np.arange(n))
    # closed, not left marked open for writing (plain h5py refuses such a file)
    with h5py.File(out / "run_1.h5", "r") as f:
        assert not f.attrs["finished"]
        assert f.attrs["ticks_recorded"] == n


# A worker's run that SIGTERM interrupts and that hears of it again while it closes (a
# dying sweep sends PDEATHSIG as each of its threads exits), and one that hears of it
# after its ticks: here sent by hand. Each closes and returns its row.
REPEATED_SIGTERM = """import os, signal
from ikaros.experiments import poolworkers


def interrupted(spec, report):
    try:
        os.kill(os.getpid(), signal.SIGTERM)        # the run is cut off here
        return "not interrupted"
    except KeyboardInterrupt:
        os.kill(os.getpid(), signal.SIGTERM)        # again, while it closes
        return "closed"


def done(spec, report):
    poolworkers.closing()                           # its ticks are done
    os.kill(os.getpid(), signal.SIGTERM)
    return "closed"


poolworkers.start(os.getppid())
print(poolworkers.run(interrupted, None), poolworkers.run(done, None))
"""


def test_a_sigterm_while_a_run_closes_lets_it_close(tmp_path):
    script = tmp_path / "worker.py"
    script.write_text(REPEATED_SIGTERM)
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    done = subprocess.run([sys.executable, str(script)], env=env, capture_output=True,
                          text=True, timeout=60)
    assert (done.returncode, done.stdout, done.stderr) == (0, "closed closed\n", "")


STOPPER = '''from ikaros import Module, Parameter


class Stopper(Module):
    """Raises KeyboardInterrupt (as Ctrl-C does) on tick ``at`` (-1: never)."""
    at = Parameter(-1, "the tick", type="int")

    def tick(self):
        if self.clock.tick == self.at:
            raise KeyboardInterrupt
'''


def test_a_sweep_in_this_process_interrupted_writes_the_table_of_every_run(tmp_path):
    from ikaros.experiments.sweeps import sweep
    (tmp_path / "Stopper.py").write_text(STOPPER)
    (tmp_path / "m.ikg").write_text('<group name="M"><module class="Sweep" name="Counter" '
                                    'min="0" max="1e9" step="1"/>'
                                    '<module class="Stopper" name="S"/></group>')
    with pytest.raises(KeyboardInterrupt):
        sweep(str(tmp_path / "m.ikg"), {"S.at": [-1, 5, -1]}, ticks=20,
              record=["Counter.OUTPUT"], out=str(tmp_path / "out"), workers=1,
              table_format="csv", progress=False)
    table = pd.read_csv(tmp_path / "out" / "results.csv")
    assert list(table["status"]) == ["ok", "interrupted", "interrupted"]
    assert list(table["ticks"]) == [20, 5, 0]
    ds = open_recording(str(tmp_path / "out" / "run_1.h5"))
    assert ds.attrs["finished"] is False
    np.testing.assert_array_equal(ds["tick"].values, np.arange(5))
