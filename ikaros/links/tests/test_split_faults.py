"""Faults of a split model: a worker stopped with SIGSTOP is found following the model's
timing and the run ends at once with no process left; a busy worker is not taken for a
stalled one; a remote worker that goes on after the main process gave up prints no
traceback; Ctrl-C prints nothing but the stop."""
import os
import signal
import socket
import subprocess
import sys
import time

import pytest

import ikaros
from ikaros.errors import RunError
from ikaros.testing import running_processes, wait_for

pytest.importorskip("zmq")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
ENV = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))

MODEL = """<group name="Split" tick_duration="0.01" where="worker" stall="" dialect="2">
  <module class="Sweep" name="Src" min="0" max="100000" step="1"/>
  <group name="Vision" process="@where" stall_ticks="@stall">
     <input name="IN"/>
     <output name="OUT"/>
     <module class="Scale" name="G" factor="2"/>
     <module class="Busy" name="B" at="-1"/>
     <connection source="IN" target="G.INPUT" delay="0"/>
     <connection source="G.OUTPUT" target="OUT" delay="0"/>
  </group>
  <module class="Add" name="Sum"/>
  <connection source="Src.OUTPUT" target="Vision.IN" delay="1"/>
  <connection source="Vision.OUT" target="Sum.INPUT1" delay="1"/>
  <connection source="Src.OUTPUT" target="Sum.INPUT2" delay="0"/>
</group>
"""
BUSY = '''import time
from ikaros import Module, Parameter


class Busy(Module):
    """Computes (holding the GIL) for 1.5 s in tick ``at``."""
    at = Parameter(-1, "the tick", type="int")

    def tick(self):
        if self.clock.tick == self.at:
            end = time.perf_counter() + 1.5
            while time.perf_counter() < end:
                pass
'''


@pytest.fixture
def model(tmp_path):
    (tmp_path / "Busy.py").write_text(BUSY)
    path = tmp_path / "split.ikg"
    path.write_text(MODEL)
    return str(path)


@pytest.mark.parametrize("stall_ticks, seconds", [("", 0.5), ("100", 1.0)])
def test_a_stopped_worker_is_found_after_the_stall_ticks_and_the_run_ends_at_once(
        model, stall_ticks, seconds):
    net = ikaros.load(model, stall=stall_ticks)
    worker = net.workers[0].process.pid
    try:
        net.run(ticks=5)
        os.kill(worker, signal.SIGSTOP)
        stopped = time.monotonic()
        with pytest.raises(RunError, match=f'worker of group "Vision".*was lost: the '
                                           f'connection was lost \\(silent for {seconds:g} s'):
            net.run(ticks=100000)
        found = time.monotonic() - stopped
        net.close()
        ended = time.monotonic() - stopped
    finally:
        if worker in running_processes():
            os.kill(worker, signal.SIGKILL)
    assert seconds - 0.1 <= found < seconds + 2.5
    assert ended < found + 4           # the stopped worker is ended, not waited for
    assert worker not in running_processes()


def test_a_worker_busy_for_longer_than_the_stall_time_is_not_lost(model):
    whole = ikaros.load(model, where="")
    whole.run(ticks=20)
    expected = whole.output("Sum.OUTPUT").tolist()
    whole.close()
    net = ikaros.load(model)            # 0.5 s without an answer is a stall
    try:
        net.set_parameter("Vision.B.at", 5)
        net.run(ticks=20)               # tick 5 takes the worker 1.5 s
        assert net.tick == 20
        assert net.output("Sum.OUTPUT").tolist() == expected
    finally:
        net.close()


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_remote_worker_that_goes_on_after_the_main_process_gave_up_prints_no_traceback(
        model, monkeypatch):
    port = free_port()
    env = dict(ENV, IKAROS_LINK_KEY="k")
    worker = subprocess.Popen([sys.executable, "-m", "ikaros", "worker", "--port", str(port)],
                              env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True)
    try:
        assert worker.stdout.readline().startswith("ikaros worker: listening")
        monkeypatch.setenv("IKAROS_LINK_KEY", "k")
        net = ikaros.load(model, where=f"127.0.0.1:{port}")
        net.run(ticks=5)
        worker.send_signal(signal.SIGSTOP)
        with pytest.raises(RunError, match="was lost"):
            net.run(ticks=100000)
        net.close()
        worker.send_signal(signal.SIGCONT)
        # it finds its main process gone, ends the session and serves the next one
        net = ikaros.load(model, where=f"127.0.0.1:{port}")
        net.run(ticks=3)
        net.close()
    finally:
        worker.send_signal(signal.SIGCONT)
        worker.send_signal(signal.SIGINT)
        _, err = worker.communicate(timeout=30)
    assert "Traceback" not in err and "ZMQError" not in err
    assert "ikaros worker: the main process is gone; the session ended" in err


def test_ctrl_c_of_a_split_model_reports_nothing_but_the_stop(model):
    for delay in (0.05, 0.3, 1.5, 3.0):    # while the worker starts, and into the run
        run = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", model], env=ENV,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               start_new_session=True)
        try:
            assert wait_for(lambda: running_processes(parent=run.pid), 60)
            time.sleep(delay)
            os.killpg(run.pid, signal.SIGINT)      # as a terminal sends Ctrl-C
            out, err = run.communicate(timeout=30)
            assert wait_for(lambda: not running_processes(run.pid), 10)
        finally:
            if running_processes(run.pid):
                os.killpg(run.pid, signal.SIGKILL)
        assert run.returncode == 0, err
        assert err == "ikaros: interrupted\n"


def test_a_signal_that_comes_while_a_message_is_held_is_handled_after_it():
    from ikaros.links.atomic import SignalHold
    seen = []
    before = signal.signal(signal.SIGINT, lambda signum, frame: seen.append("handled"))
    hold = SignalHold()
    hold.install()
    try:
        with hold:
            signal.raise_signal(signal.SIGINT)
            seen.append("message sent")
        signal.raise_signal(signal.SIGINT)      # outside: at once
        seen.append("after")
    finally:
        hold.uninstall()
        mine = signal.signal(signal.SIGINT, before)
    assert seen == ["message sent", "handled", "handled", "after"]
    assert mine != hold._handler            # the handler given back


def test_a_stall_ticks_that_is_not_a_whole_number_is_a_load_error(model):
    from ikaros.errors import ModelError
    for bad in ("x", "0", "1.5"):
        with pytest.raises(ModelError, match=f'split.ikg:3: <group name="Vision">: '
                                             f'stall_ticks "{bad}" must be a whole number '
                                             f'of ticks >= 1'):
            ikaros.load(model, stall=bad)


@pytest.mark.slow
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_after_the_main_process_was_stopped_until_its_worker_gave_up_ends_at_once(
        model, signum):
    """SIGSTOP the main process until its worker has given up on it (it hears nothing for
    its heartbeat timeout, ends its session and exits), then SIGCONT and Ctrl-C (or
    SIGTERM): the run ends at once (no wait for the gone worker's answer, so the 2 s
    watchdog of Ctrl-C does not force the exit), with one line and status 0."""
    folder = os.path.dirname(model)
    ticks = os.path.join(folder, "ticks.txt")          # a line a tick, flushed
    with open(os.path.join(folder, "written.ikg"), "w") as f:
        f.write(MODEL.rstrip()[:-len("</group>")] + '<module class="OutputFile" name="Out" '
                'filename="ticks.txt"><column name="X"/></module>'
                '<connection source="Sum.OUTPUT" target="Out.X"/></group>\n')
    run = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", f.name], env=ENV,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           start_new_session=True)
    try:
        assert wait_for(lambda: running_processes(parent=run.pid), 60)
        worker = running_processes(parent=run.pid)[0]
        assert wait_for(lambda: _lines(ticks) >= 3, 60)     # the header, then two ticks
        os.kill(run.pid, signal.SIGSTOP)
        assert wait_for(lambda: worker not in running_processes(), 60)
        os.kill(run.pid, signal.SIGCONT)
        os.kill(run.pid, signum)
        _, err = run.communicate(timeout=60)
    finally:
        if run.poll() is None:
            os.killpg(run.pid, signal.SIGKILL)
            run.wait()
    assert (run.returncode, err) == (0, "ikaros: interrupted\n")



def _lines(path: str) -> int:
    try:
        with open(path) as f:
            return len(f.read().splitlines())
    except OSError:
        return 0
