"""A recording whose writes fail (a file-size limit stands in for a full disk: the write
fails the same way, on any file system and without mounting one), an interrupted recording,
and the flush interval."""
import os
import re
import resource
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")
pytest.importorskip("xarray")

from ikaros.errors import RunError  # noqa: E402
from ikaros.experiments import open_recording  # noqa: E402
from ikaros.testing import load_body, wait_for  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))

# Counter.OUTPUT is k + 1 on tick k
BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Sweep" name="Grid" outputsize_x="8" outputsize_y="4" min="0" max="100000000"
        step="0.5"/>
"""


def model(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">{BODY}</group>\n')
    return str(path)


def ikaros_limited(limit_bytes: int, *args, timeout=120):
    """``ikaros ARGS`` in a process whose files may not grow past ``limit_bytes`` (a write
    past it fails with EFBIG, as one on a full disk fails with ENOSPC)."""
    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.run([sys.executable, "-m", "ikaros", *args], env=env,
                          preexec_fn=limit, capture_output=True, text=True, timeout=timeout)


def stored_ticks(stderr: str, out) -> int:
    """The ticks the one error line says the file holds (checked to run from tick 0)."""
    found = re.search(rf"writing the recording {re.escape(str(out))} failed \(File too "
                      rf"large\); it holds (\d+) ticks \(0 to (\d+)\)", stderr)
    assert found, stderr
    n = int(found.group(1))
    assert int(found.group(2)) == n - 1
    return n


def assert_rows_are_ticks(out, n: int) -> None:
    ds = open_recording(str(out))
    assert ds.sizes["tick"] == n
    assert ds.attrs["finished"] is False
    k = np.arange(n)
    np.testing.assert_array_equal(ds["tick"].values, k)
    np.testing.assert_allclose(ds["time"].values, k * 0.01)
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], k + 1)
    real = ds["real_time"].values
    assert real[0] == 0 and np.all(np.diff(real) >= 0)


def test_a_disk_that_fills_stops_the_run_with_one_line_and_the_file_holds_what_it_says(
        tmp_path):
    out = tmp_path / "run.h5"
    done = ikaros_limited(1 << 20, "-b", "-q", "-s", "100000000", model(tmp_path),
                          "--record", str(out), "--record-flush", "0.05")
    assert done.returncode == 1, done.stderr
    assert "Traceback" not in done.stderr and "OSError" not in done.stderr
    assert "the run stops" in done.stderr
    n = stored_ticks(done.stderr, out)
    assert n > 0
    assert_rows_are_ticks(out, n)


def test_with_record_on_error_continue_the_run_goes_to_its_end_without_recording(tmp_path):
    out = tmp_path / "run.h5"
    done = ikaros_limited(1 << 20, "-b", "-s", "200000", model(tmp_path), "--record",
                          str(out), "--record-flush", "0.05", "--record-on-error",
                          "continue")
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    assert "the run goes on without recording" in done.stderr
    lines = [line for line in done.stderr.splitlines() if "run.h5" in line]
    assert len(lines) == 1, done.stderr
    assert_rows_are_ticks(out, stored_ticks(done.stderr, out))


def test_a_disk_full_at_the_start_leaves_no_file(tmp_path):
    out = tmp_path / "run.h5"
    done = ikaros_limited(2048, "-b", "-s", "10", model(tmp_path), "--record", str(out))
    assert done.returncode == 1, done.stderr
    assert "Traceback" not in done.stderr
    assert f"ikaros: error: --record: cannot write the recording {out}: File too large" \
        in done.stderr
    assert not out.exists()


def test_the_default_stops_the_run_and_continue_goes_on_with_a_warning(tmp_path):
    for on_error in ("stop", "continue"):
        net = load_body(tmp_path, BODY)
        net.log_level = -1
        path = str(tmp_path / f"{on_error}.h5")
        recorder = net.record(path, on_error=on_error)
        net.run(ticks=5)
        recorder._fail(OSError(28, "No space left on device"))  # as the writer thread does
        if on_error == "stop":
            with pytest.raises(RunError, match="No space left on device"):
                net.run(ticks=5)
            assert net.tick == 6          # the tick in which it was heard of
        else:
            net.run(ticks=5)
            assert net.tick == 10
        net.close()
        message = [m for _, _, _, m in net.log if "No space" in m]
        assert message == [f"writing the recording {path} failed (No space left on "
                           f"device); it holds no ticks (the file is removed); the run "
                           f"{'stops' if on_error == 'stop' else 'goes on without recording'}"]
        assert recorder.failure == message[0]
        assert not os.path.exists(path)


def test_an_interrupted_recording_is_not_finished_and_holds_its_ticks(tmp_path):
    net = load_body(tmp_path, BODY)
    path = str(tmp_path / "run.h5")
    with pytest.raises(KeyboardInterrupt):
        with net.record(path):
            net.run(ticks=40)
            raise KeyboardInterrupt
    net.close()
    ds = open_recording(path)
    assert ds.attrs["finished"] is False
    np.testing.assert_array_equal(ds["tick"].values, np.arange(40))
    with h5py.File(path, "r") as f:
        assert f.attrs["ticks_recorded"] == 40
    with net.record(str(tmp_path / "whole.h5")):
        pass
    assert open_recording(str(tmp_path / "whole.h5")).attrs["finished"] is True


def test_the_flush_interval_is_a_setting(tmp_path):
    net = load_body(tmp_path, BODY)
    with pytest.raises(ValueError, match="flush_seconds must be a number >= 0, not -1"):
        net.record(str(tmp_path / "bad.h5"), flush_seconds=-1)
    with pytest.raises(ValueError, match='on_error must be "stop" or "continue", not "x"'):
        net.record(str(tmp_path / "bad.h5"), on_error="x")
    recorder = net.record(str(tmp_path / "run.h5"), flush_seconds=0)
    assert recorder.flush_seconds == 0
    net.run(ticks=4)
    # with 0, each tick's row is handed over at the start of the next tick, written and
    # flushed at once: ticks 0 to 2 are stored while the run waits after tick 3
    deadline = time.monotonic() + 30
    while recorder.stored < 3 and time.monotonic() < deadline:
        time.sleep(0.01)
    assert recorder.stored == 3
    with h5py.File(tmp_path / "run.h5", "r", swmr=True) as f:
        assert f["stored"][0] == 3
    recorder.close()
    net.close()
    np.testing.assert_array_equal(open_recording(str(tmp_path / "run.h5"))["tick"].values,
                                  np.arange(4))


def test_readers_stop_at_the_rows_the_file_counts_as_stored(tmp_path):
    net = load_body(tmp_path, BODY)
    path = str(tmp_path / "run.h5")
    with net.record(path, only="Counter.OUTPUT"):
        net.run(ticks=10)
    net.close()
    with h5py.File(path, "a") as f:        # as if the run was killed with rows 4-9 half
        assert f["stored"][0] == 10        # written
        f["stored"][:] = [4, ~4]           # (the count, and its complement)
        f.attrs.modify("finished", False)
        f.attrs.modify("ticks_recorded", 0)
    assert open_recording(path).sizes["tick"] == 4
    replay = load_body(tmp_path, f'<module class="Replay" name="R" filename="{path}" '
                                 f'signal="Counter.OUTPUT"/>')
    replay.log_level = -1
    replay.run(ticks=100)           # ends with the last row kept: 4 ticks
    assert replay.tick == 4
    np.testing.assert_array_equal(replay.output("R.OUTPUT"), [4])
    replay.close()


def test_a_recording_run_ended_by_sigterm_keeps_every_tick_and_is_not_finished(tmp_path):
    out = tmp_path / "run.h5"
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    run = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-q", "-s", "1000000000",
                            model(tmp_path), "--record", str(out), "--record-flush", "0.1"],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert wait_for(lambda: out.exists() and _rows(out) > 1000, 60, 0.1)
        run.send_signal(signal.SIGTERM)
        _, err = run.communicate(timeout=30)
    finally:
        if run.poll() is None:
            run.kill()
    assert run.returncode == 0 and err == "ikaros: interrupted\n"
    ds = open_recording(str(out))
    n = ds.sizes["tick"]
    assert ds.attrs["finished"] is False
    np.testing.assert_array_equal(ds["tick"].values, np.arange(n))
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], np.arange(n) + 1)
    with h5py.File(out, "r") as f:
        assert f.attrs["ticks_recorded"] == n == f["stored"][0]


def _rows(path) -> int:
    try:
        return open_recording(str(path)).sizes["tick"]
    except OSError:
        return 0
