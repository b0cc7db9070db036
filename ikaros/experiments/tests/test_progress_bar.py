"""The progress bar of batch runs: on a terminal only, not with -q."""
import fcntl
import os
import pty
import select
import struct
import subprocess
import sys
import termios
import time

import pytest

pytest.importorskip("tqdm")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
MODEL = '<group name="P"><module class="Sweep" name="S" step="1" max="1e9"/></group>\n'


def run(tmp_path, *options, terminal: bool, command: tuple = ("-b", "-s", "30000"),
        rows: int = 24, python_path: str = "") -> str:
    """Run 30000 ticks with stderr on a pseudo-terminal of ``rows`` rows (or a pipe); what
    stderr got."""
    path = tmp_path / "model.ikg"
    path.write_text(MODEL)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        p for p in (python_path, ROOT, os.environ.get("PYTHONPATH", "")) if p),
        COLUMNS="100")
    command = [sys.executable, "-m", "ikaros", *command, *options, str(path)]
    if not terminal:
        done = subprocess.run(command, env=env, capture_output=True, timeout=60)
        assert done.returncode == 0
        return done.stderr.decode()
    primary, secondary = pty.openpty()
    fcntl.ioctl(secondary, termios.TIOCSWINSZ, struct.pack("HHHH", rows, 100, 0, 0))
    proc = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=secondary)
    os.close(secondary)
    chunks, deadline = [], time.monotonic() + 60
    try:
        while time.monotonic() < deadline:
            ready, _, _ = select.select([primary], [], [], 0.5)
            if ready:
                try:
                    data = os.read(primary, 4096)
                except OSError:       # the other end closed
                    break
                if not data:
                    break
                chunks.append(data)
            elif proc.poll() is not None:
                break
        assert proc.wait(timeout=30) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
        os.close(primary)
    return b"".join(chunks).decode(errors="replace")


def test_a_terminal_shows_ticks_done_ticks_per_second_and_time_left(tmp_path):
    text = run(tmp_path, terminal=True)
    assert "30000/30000" in text
    assert "tick/s" in text
    assert "<00:00" in text               # time left, at the end


def test_nothing_extra_when_not_a_terminal_or_quiet(tmp_path):
    assert run(tmp_path, terminal=False) == ""
    assert run(tmp_path, "-q", terminal=True) == ""


def test_a_sweep_shows_the_runs_done_on_a_terminal(tmp_path):
    text = run(tmp_path, terminal=True, command=("sweep", "--set", "S.step=1:4", "--ticks",
                                                 "100", "--workers", "2"))
    assert "4/4" in text and "run/s" in text
    assert "ikaros sweep: 4 runs, 4 ok, 0 failed" in text


def test_a_terminal_that_gives_no_size_shows_the_bar_too(tmp_path):
    # a new pseudo-terminal says 0 rows; tqdm then drew nothing at all
    text = run(tmp_path, terminal=True, rows=0)
    assert "30000/30000" in text


def test_without_tqdm_a_terminal_is_told_what_gives_the_bar(tmp_path):
    hidden = tmp_path / "no_tqdm" / "tqdm"
    hidden.mkdir(parents=True)
    (hidden / "__init__.py").write_text('raise ImportError("No module named tqdm")\n')
    text = run(tmp_path, terminal=True, python_path=str(hidden.parent))
    assert "pip install tqdm (or 'ikaros[progress]') for a progress bar" in text
    assert "tick/s" not in text


@pytest.mark.parametrize("workers", ["1", "2"])
def test_a_sweep_shows_a_bar_per_run_with_its_ticks(tmp_path, workers):
    text = run(tmp_path, terminal=True, command=("sweep", "--set", "S.step=1:3", "--ticks",
                                                 "5000", "--workers", workers))
    for k in range(3):
        assert f"run {k}:" in text
    assert "/5000 " in text and "tick/s" in text
    assert "3/3" in text and "ikaros sweep: 3 runs, 3 ok, 0 failed" in text
