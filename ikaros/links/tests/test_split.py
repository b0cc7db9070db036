"""A group in another kernel process: the same values tick by tick as one process."""
import os
import signal
import socket
import subprocess
import sys
import time

import pytest

import ikaros
from ikaros.errors import ModelError, RunError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))

MODEL = """<group name="Split" where="worker" alias_where="worker" dialect="2">
  <module class="Sweep" name="Src" min="0" max="100" step="1"/>
  <group name="Vision" process="@where">
     <input name="IN"/>
     <output name="OUT"/>
     <module class="Scale" name="G" factor="2"/>
     <module class="Sweep" name="Own" min="0" max="10" step="3"/>
     <connection source="IN" target="G.INPUT" delay="0"/>
     <connection source="G.OUTPUT" target="OUT" delay="0"/>
  </group>
  <group name="Motor" process="@alias_where">
     <input name="IN" target="P.INPUT"/>
     <output name="OUT" source="P.OUTPUT"/>
     <module class="Scale" name="P" factor="-1"/>
  </group>
  <module class="Add" name="Sum"/>
  <module class="Scale" name="Window" factor="1"/>
  <module class="Add" name="Both"/>
  <connection source="Src.OUTPUT" target="Vision.IN" delay="1"/>
  <connection source="Vision.OUT" target="Sum.INPUT1" delay="2"/>
  <connection source="Src.OUTPUT" target="Sum.INPUT2" delay="0"/>
  <connection source="Vision.Own.OUTPUT" target="Window.INPUT" delay="1:3"/>
  <connection source="Vision.OUT" target="Motor.IN" delay="3"/>
  <connection source="Motor.OUT" target="Both.INPUT1"/>
  <connection source="Vision.G.OUTPUT" target="Both.INPUT2"/>
</group>
"""
OUTPUTS = ["Src.OUTPUT", "Sum.OUTPUT", "Window.OUTPUT", "Both.OUTPUT"]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def trace(net, ticks=25):
    rows = []
    try:
        for _ in range(ticks):
            net.step()
            rows.append([net.output(p).tolist() for p in OUTPUTS])
    finally:
        net.close()
    return rows


@pytest.fixture
def model(tmp_path):
    path = tmp_path / "split.ikg"
    path.write_text(MODEL)
    return str(path)


def test_groups_in_worker_processes_give_the_values_of_one_process(model):
    one = ikaros.load(model, where="", alias_where="")
    assert type(one).__name__ == "Network"
    expected = trace(one)
    split = ikaros.load(model)
    assert type(split).__name__ == "SplitNetwork" and len(split.workers) == 2
    assert sorted(split.modules) == sorted(one.modules)
    assert [m.path for m in split.schedule] == ["Src", "Sum", "Window", "Both"]
    processes = [w.process for w in split.workers]
    assert trace(split) == expected
    assert all(p is None for p in [w.process for w in split.workers])
    assert all(p.returncode == 0 for p in processes)
    # the values are not trivial: delays of 1, 2, 1:3 (the longest first: an Ikaros 2
    # file), 3 and the hops through groups
    assert expected[5] == [[6.0], [12.0], [[9.0], [0.0], [3.0]], [6.0]]


def test_a_zero_delay_connection_between_processes_is_a_load_error(tmp_path):
    (tmp_path / "m.ikg").write_text(MODEL.replace(
        'target="Vision.IN" delay="1"', 'target="Vision.IN" delay="0"'))
    with pytest.raises(ModelError, match=r'm.ikg:\d+.*Src.OUTPUT -> Vision.G.INPUT.*'
                                         r'delay 0.*at least 1'):
        ikaros.load(str(tmp_path / "m.ikg"))


def test_nested_process_groups_are_a_load_error(tmp_path):
    (tmp_path / "m.ikg").write_text(
        '<group name="T"><group name="A" process="worker"><group name="B" process="worker">'
        '<module class="Constant" name="C" data="1"/></group></group></group>')
    with pytest.raises(ModelError, match="can not be nested"):
        ikaros.load(str(tmp_path / "m.ikg"))


def start_worker(port, key):
    env = dict(os.environ, IKAROS_LINK_KEY=key)
    worker = subprocess.Popen([sys.executable, "-m", "ikaros", "worker", "--port", str(port)],
                              cwd=ROOT, env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    line = worker.stdout.readline()
    assert line.startswith(f"ikaros worker: listening on tcp://127.0.0.1:{port}"), line
    return worker


def stop(process):
    process.send_signal(signal.SIGINT)
    try:
        process.wait(10)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def test_a_running_worker_serves_groups_by_address_with_a_key(model, monkeypatch):
    expected = trace(ikaros.load(model, where="", alias_where=""))
    port = free_port()
    worker = start_worker(port, "s3cret")
    try:
        monkeypatch.setenv("IKAROS_LINK_KEY", "s3cret")
        # the worker serves one model at a time, and the next one after it
        assert trace(ikaros.load(model, where=f"127.0.0.1:{port}")) == expected
        assert trace(ikaros.load(model, where=f"tcp://127.0.0.1:{port}")) == expected
        monkeypatch.setenv("IKAROS_LINK_KEY", "wrong")
        with pytest.raises(ModelError, match="refused.*another key"):
            ikaros.load(model, where=f"127.0.0.1:{port}")
    finally:
        stop(worker)
    assert "refused a request" in worker.stderr.read()


def test_another_machine_needs_a_key(model, monkeypatch):
    monkeypatch.delenv("IKAROS_LINK_KEY", raising=False)
    with pytest.raises(ModelError, match="needs a shared key"):
        ikaros.load(model, where="192.0.2.1:9200")


def test_a_lost_worker_ends_the_run_with_an_error_naming_it(model):
    net = ikaros.load(model, alias_where="")
    try:
        net.run(ticks=3)
        net.workers[0].process.send_signal(signal.SIGKILL)
        start = time.monotonic()
        with pytest.raises(RunError, match='worker of group "Vision".*was lost'):
            net.run(ticks=100)
        assert time.monotonic() - start < 10
        assert net.stopped
    finally:
        net.close()


def test_a_worker_for_other_machines_needs_a_key():
    env = {k: v for k, v in os.environ.items() if k != "IKAROS_LINK_KEY"}
    r = subprocess.run([sys.executable, "-m", "ikaros", "worker", "--bind", "0.0.0.0",
                        "--port", "0"], cwd=ROOT, env=env, capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 1
    assert "ikaros worker: error:" in r.stderr and "needs a shared key" in r.stderr


CMD = """from ikaros import Module, Output, Parameter


class Cmd(Module):
    \"\"\"Test module: the command "set" sets OUTPUT to x; prints on tick 2; ends the run
    on tick ``last``.\"\"\"
    last = Parameter(1000, "the tick that ends the run", type="int")
    OUTPUT = Output("the value last set", size=1)

    def command(self, name, x=0, y=0, value=None):
        if name == "set":
            self.OUTPUT[0] = x

    def tick(self):
        if self.clock.tick == 2:
            self.print("hello from tick 2")
        if self.clock.tick == self.last:
            self.end_of_file("done")
"""


def test_parameters_commands_and_notifications_cross_to_and_from_a_worker(tmp_path, capsys):
    from ikaros.module import END_OF_FILE, PRINT
    (tmp_path / "Cmd.py").write_text(CMD)
    (tmp_path / "m.ikg").write_text(
        '<group name="T"><group name="W" process="worker"><module class="Cmd" name="C"/>'
        '<module class="Sweep" name="S" min="0" max="100" step="1"/>'
        '</group><module class="Scale" name="R" factor="1"/>'
        '<connection source="W.C.OUTPUT" target="R.INPUT"/></group>')
    net = ikaros.load(str(tmp_path / "m.ikg"))
    try:
        inside = net.buffer_array("W.S.OUTPUT")          # brought over from now on
        assert inside.tolist() == [0]
        net.run(ticks=3)
        assert inside.tolist() == [3]                     # the Sweep's value of tick 2
        assert (2, PRINT, "W.C", "hello from tick 2") in net.log
        assert capsys.readouterr().out.count("hello from tick 2") == 1     # printed here
        net.command("W.C", "set", 5)
        net.step()
        assert net.output("W.C.OUTPUT").tolist() == [5]
        net.step()
        assert net.output("R.OUTPUT").tolist() == [5]
        net.set_parameter("W.C.last", 7)
        assert net.parameter("W.C.last") == 7
        net.run(ticks=100)
        assert net.tick == 8 and net.stopped
        assert net.stop_reason == (END_OF_FILE, "done")
    finally:
        net.close()


def test_a_busy_worker_refuses_and_a_lost_remote_worker_ends_the_run(model, monkeypatch):
    port = free_port()
    worker = start_worker(port, "k")
    monkeypatch.setenv("IKAROS_LINK_KEY", "k")
    net = ikaros.load(model, where=f"127.0.0.1:{port}", alias_where="")
    try:
        net.run(ticks=2)
        with pytest.raises(ModelError, match="busy with another model"):
            ikaros.load(model, where=f"127.0.0.1:{port}", alias_where="")
        net.run(ticks=2)                        # the first session goes on
        worker.kill()
        worker.wait(10)
        start = time.monotonic()
        with pytest.raises(RunError, match=f'worker of group "Vision".*127.0.0.1:{port} was '
                                           f'lost: the connection was lost'):
            net.run(ticks=1000)
        assert time.monotonic() - start < 10
    finally:
        net.close()
        stop(worker)
