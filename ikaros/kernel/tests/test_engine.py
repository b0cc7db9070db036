"""The run engine: modes through the controller, timing figures, threads, asynchronous
modules, period and phase."""
import time

import numpy as np
import pytest

import ikaros
from ikaros.kernel.control import PAUSE, PLAY, REALTIME

SLOW = '''
import time
import numpy as np
from ikaros.module import Input, Module, Output, Parameter


class Slow(Module):
    """Adds one to a counter per job; each job sleeps ``seconds``."""
    seconds = Parameter(0.05, "how long a tick takes")
    gain = Parameter(1.0, "added per job")
    OUTPUT = Output("the count", size="1")

    def init(self):
        self.OUTPUT[0] = 0
        self.jobs_running = 0
        self.most_at_once = 0

    def tick(self):
        self.jobs_running += 1
        self.most_at_once = max(self.most_at_once, self.jobs_running)
        time.sleep(self.seconds)
        self.OUTPUT[0] += self.gain
        self.jobs_running -= 1
'''


def _model(tmp_path, text, **overrides):
    (tmp_path / "m.ikg").write_text(text)
    return ikaros.load(str(tmp_path / "m.ikg"), **overrides)


RAMP = '''<group name="R">
    <module class="Sweep" name="S" min="0" max="1000000000" step="1"/>
    <module class="Constant" name="C" data="1"/>
</group>'''


def test_controller_steps_exactly_one_tick_in_a_background_thread(tmp_path):
    net = _model(tmp_path, RAMP)
    c = net.controller
    c.start(PAUSE)
    try:
        time.sleep(0.1)
        assert net.tick == 0
        c.step()
        deadline = time.time() + 5
        while net.tick < 1 and time.time() < deadline:
            time.sleep(0.01)
        time.sleep(0.1)
        assert net.tick == 1 and c.state == PAUSE
        assert c.call(net.output, "S.OUTPUT").tolist() == [1]
        c.play()
        time.sleep(0.2)
        c.pause()
        time.sleep(0.1)
        ticks = net.tick
        assert ticks > 10
        time.sleep(0.1)
        assert net.tick == ticks
        c.call(net.set_parameter, "C.data", 42)
        c.step()
        time.sleep(0.2)
        assert net.tick == ticks + 1
        assert c.call(net.output, "C.OUTPUT").tolist() == [42]
    finally:
        c.stop()
        c.join(5)
    assert not c._thread.is_alive()


def test_real_time_keeps_absolute_deadlines_and_reports_lag(tmp_path):
    net = _model(tmp_path, RAMP, tick_duration=0.005)
    start = time.perf_counter()
    net.run(ticks=40, real_time=True)
    elapsed = time.perf_counter() - start
    f = net.figures()
    assert net.tick == 40
    assert 0.19 <= elapsed < 0.5            # tick 39 is due 39 * 5 ms after the first
    assert f["lag_max"] < 0.05 and f["lag_p99"] <= f["lag_max"]
    assert 0 < f["actual_tick_duration"] < 0.05
    assert 0.2 < f["idle"] <= 1.0            # most of each 5 ms tick is spent waiting
    assert f["state"] in (PLAY, REALTIME, "pause")


def test_a_long_stall_resynchronises_instead_of_bursting(tmp_path):
    (tmp_path / "Slow.py").write_text(SLOW)
    net = _model(tmp_path, '<group name="G" tick_duration="0.01"><module class="Slow" '
                           'name="S" seconds="0"/></group>')
    ends = {}

    def stall_at_tick_5():
        ends[net.tick] = time.perf_counter()
        if net.tick in (5, 6):
            net.set_parameter("S.seconds", 0.3 if net.tick == 5 else 0)   # tick 5 takes 300 ms

    net.controller.tick_hooks.append(stall_at_tick_5)
    net.run(ticks=16, real_time=True)
    # without resync the 10 ticks after the stall would run back to back to catch up
    assert ends[16] - ends[6] >= 0.08
    assert net.figures()["resyncs"] == 1


def test_time_between_two_real_time_runs_is_not_owed(tmp_path):
    (tmp_path / "Slow.py").write_text(SLOW)
    net = _model(tmp_path, '<group name="G" tick_duration="0.01"><module class="Slow" '
                           'name="S" seconds="0"/></group>')
    net.run(ticks=3, real_time=True)
    time.sleep(0.3)
    start = time.perf_counter()
    net.run(ticks=10, real_time=True)
    assert time.perf_counter() - start >= 0.08      # no burst to catch up the 300 ms
    assert net.figures()["resyncs"] == 0 and net.figures()["state"] == "pause"


def test_profiling_measures_each_module(tmp_path):
    net = _model(tmp_path, RAMP)
    net.run(ticks=10)
    assert net.module_figures()[0]["count"] == 0         # off by default
    net.profiling = True
    net.run(ticks=25)
    m = net.module_figures()[0]
    assert m["module"] == "S" and m["count"] == 25 and 0 < m["mean"] <= m["max"]
    assert "S" in net.profile_text() and "ticks/s" in net.profile_text()


PIPELINES = '''<group name="P" threads="{threads}">
    <module class="Randomizer" name="R1" outputsize_x="40" outputsize_y="30" seed="1"/>
    <module class="Randomizer" name="R2" outputsize_x="40" outputsize_y="30" seed="2"/>
    <module class="Scale" name="A1" factor="2"/>
    <module class="Scale" name="A2" factor="3"/>
    <module class="Add" name="Mix"/>
    <module class="Add" name="Loop"/>
    <connection source="R1.OUTPUT" target="A1.INPUT" delay="0"/>
    <connection source="R2.OUTPUT" target="A2.INPUT" delay="0"/>
    <connection source="A1.OUTPUT" target="Mix.INPUT1"/>
    <connection source="A2.OUTPUT" target="Mix.INPUT2" delay="2"/>
    <connection source="Mix.OUTPUT" target="Loop.INPUT1"/>
    <connection source="Loop.OUTPUT" target="Loop.INPUT2"/>
</group>'''


def test_threads_give_the_same_results_tick_by_tick(tmp_path):
    one = _model(tmp_path, PIPELINES.format(threads=1))
    (tmp_path / "two").mkdir()
    two = ikaros.load(str(_write(tmp_path / "two", PIPELINES.format(threads=2))))
    assert two.plan.pool is not None and len(two.plan.lanes) == 2
    for _ in range(20):
        one.step()
        two.step()
        for path in ("A1.OUTPUT", "A2.OUTPUT", "Mix.OUTPUT", "Loop.OUTPUT"):
            assert np.array_equal(one.output(path), two.output(path)), path
    two.close()


def _write(folder, text):
    (folder / "m.ikg").write_text(text)
    return folder / "m.ikg"


def test_async_module_runs_in_the_background_one_job_at_a_time(tmp_path):
    (tmp_path / "Slow.py").write_text(SLOW)
    net = _model(tmp_path, '<group name="G"><module class="Slow" name="S" async="yes" '
                           'seconds="0.05"/></group>')
    job = net.async_modules[net.modules["S"]]
    start = time.perf_counter()
    net.step()                                   # launches job 1, does not wait for it
    assert time.perf_counter() - start < 0.04
    assert net.output("S.OUTPUT").tolist() == [0]   # last finished value
    net.set_parameter("S.gain", 10)              # queued until job 1 has finished
    assert net.modules["S"].module.gain == 1
    time.sleep(0.1)
    net.step()                                   # publishes job 1, applies gain, starts 2
    assert net.output("S.OUTPUT").tolist() == [1]
    assert net.modules["S"].module.gain == 10
    for _ in range(5):
        net.step()                               # job 2 still running: nothing new
    assert net.output("S.OUTPUT").tolist() == [1]
    time.sleep(0.1)
    net.step()
    assert net.output("S.OUTPUT").tolist() == [11]
    net.close()
    assert net.modules["S"].module.most_at_once == 1
    assert job.completed >= 3


def test_period_and_phase(tmp_path):
    net = _model(tmp_path, '''<group name="G">
        <module class="Sweep" name="Every3" min="0" max="100" step="1" period="3" phase="1"/>
        <module class="Sweep" name="Always" min="0" max="100" step="1"/>
    </group>''')
    seen = []
    for _ in range(7):
        net.step()
        seen.append(int(net.output("Every3.OUTPUT")[0]))
    assert seen == [0, 1, 1, 1, 2, 2, 2]        # ticks 1 and 4 run
    assert net.output("Always.OUTPUT").tolist() == [7]
    with pytest.raises(ikaros.ModelError, match="period must be >= 1"):
        _model(tmp_path, '<group name="G"><module class="Sweep" name="S" period="2" '
                         'phase="2"/></group>')


FUSABLE = '''<group name="F">
    <module class="Sweep" name="Ramp" min="0" max="50" step="0.5" outputsize="3"/>
    <module class="Constant" name="K" data="1 2 3"/>
    <module class="Scale" name="S1" factor="2"/>
    <module class="Scale" name="S2" factor="-1.5"/>
    <module class="Scale" name="S3" factor="0.25"/>
    <module class="Add" name="A1"/>
    <module class="Add" name="A2"/>
    <module class="Multiply" name="M"/>
    <module class="Subtract" name="D"/>
    <module class="Scale" name="G1" factor="0.3"/>
    <module class="Scale" name="G2" factor="-0.7"/>
    <connection source="Ramp.OUTPUT" target="G1.INPUT"/>
    <connection source="K.OUTPUT" target="G1.SCALE"/>
    <connection source="K.OUTPUT" target="G2.INPUT"/>
    <connection source="Ramp.OUTPUT" target="G2.SCALE" sourceoffset="2" size="1"/>
    <connection source="Ramp.OUTPUT" target="S1.INPUT" delay="0"/>
    <connection source="K.OUTPUT" target="S2.INPUT" delay="0"/>
    <connection source="Ramp.OUTPUT" target="S3.INPUT"/>
    <connection source="S1.OUTPUT" target="A1.INPUT1" delay="0"/>
    <connection source="S2.OUTPUT" target="A1.INPUT2" delay="0"/>
    <connection source="S3.OUTPUT" target="A2.INPUT1" delay="0"/>
    <connection source="A1.OUTPUT" target="A2.INPUT2"/>
    <connection source="A1.OUTPUT" target="M.INPUT1" delay="0"/>
    <connection source="A2.OUTPUT" target="M.INPUT2" delay="0"/>
    <connection source="M.OUTPUT" target="D.INPUT1" delay="0"/>
    <connection source="K.OUTPUT" target="D.INPUT2" delay="2"/>
</group>'''


def test_fused_element_wise_modules_compute_what_their_ticks_compute(tmp_path):
    fused = _model(tmp_path, FUSABLE, compiled="no")   # fusion, not the compiled tick
    assert {i.path for i in fused.plan.fused} == {"S1", "S2", "G1", "G2"}
    plain = ikaros.load(str(tmp_path / "m.ikg"))
    plain.profiling = True                       # measuring per module: no fusion
    for tick in range(12):
        if tick == 5:
            for net in (fused, plain):
                net.set_parameter("S2.factor", 4)
        fused.step()
        plain.step()
        for path in ("S1", "S2", "S3", "A1", "A2", "M", "D", "G1", "G2"):
            assert np.array_equal(fused.output(path + ".OUTPUT"),
                                  plain.output(path + ".OUTPUT")), (tick, path)
    # tick 11: ramp 6, S1 12, S2 4*[1,2,3], A1 = [16, 20, 24]
    assert fused.output("A1.OUTPUT").tolist() == [16, 20, 24]


def test_steps_asked_for_in_a_row_each_run_one_tick(tmp_path):
    net = _model(tmp_path, RAMP)
    c = net.controller
    c.start(PAUSE)
    try:
        for _ in range(5):
            c.step()
        deadline = time.time() + 5
        while net.tick < 5 and time.time() < deadline:
            time.sleep(0.01)
        time.sleep(0.2)
        assert net.tick == 5 and c.state == PAUSE
    finally:
        c.stop()
        c.join(5)
