"""Tests of the System module: the clock's values, and the rates measured with a fake time."""
import os

import numpy as np
import pytest

from ikaros.modules.utility import System as system_module
from ikaros.testing import load_body as load

OUTPUTS = ("TICK", "TIME", "TICK_DURATION", "REAL_TIME", "LAG", "TICKS_PER_SECOND",
           "CPU_USAGE", "CORES")


def values(net) -> dict:
    return {name: float(net.output(f"S.{name}")[0]) for name in OUTPUTS}


class FakeTime:
    """Wall-clock and CPU time that the test moves on."""

    def __init__(self):
        self.wall = self.cpu = 0.0

    def perf_counter(self):
        return self.wall

    def process_time(self):
        return self.cpu


def test_the_clock_each_tick(tmp_path):
    net = load(tmp_path, '<module class="System" name="S"/>', tick_duration="0.25",
               dialect=2)        # ticks from 0
    try:
        before = values(net)
        assert before["TICK"] == -1 and before["TIME"] == 0
        assert before["TICKS_PER_SECOND"] == 0 and before["CPU_USAGE"] == 0
        assert before["CORES"] == (os.cpu_count() or 1)
        for k in range(3):
            net.step()
            now = values(net)
            assert (now["TICK"], now["TIME"], now["TICK_DURATION"], now["LAG"]) == \
                (k, k * 0.25, 0.25, 0)
            assert now["REAL_TIME"] == np.float32(net.clock.real_time)
        assert now["REAL_TIME"] > before["REAL_TIME"]
    finally:
        net.close()


def test_rates_over_the_window(tmp_path, monkeypatch):
    fake = FakeTime()
    monkeypatch.setattr(system_module, "time", fake)
    net = load(tmp_path, '<module class="System" name="S" window="3"/>')
    try:
        cores = os.cpu_count() or 1
        rates = []
        for wall, cpu in ((1.0, 0.5), (1.5, 0.75), (2.0, 1.0), (4.0, 1.25)):
            fake.wall, fake.cpu = wall, cpu
            net.step()
            rates.append((float(net.output("S.TICKS_PER_SECOND")[0]),
                          float(net.output("S.CPU_USAGE")[0])))
        # the window: 1 tick (no rate yet), then ticks at 1.0, 1.5; 1.0..2.0; 1.5..4.0
        assert rates == [(0, 0), (2, pytest.approx(0.5 / cores)),
                         (2, pytest.approx(0.5 / cores)),
                         (pytest.approx(0.8), pytest.approx(0.2 / cores))]
    finally:
        net.close()


def test_lag_is_the_real_time_lag_of_the_tick(tmp_path):
    net = load(tmp_path, '<module class="System" name="S"/>', tick_duration="0.01")
    try:
        net.run(3, real_time=True)
        assert net.output("S.LAG")[0] == np.float32(net.timing.lag) >= 0
        net.step()                                   # not real time: no lag
        assert net.output("S.LAG").tolist() == [0]
    finally:
        net.close()


def test_the_window_is_fixed_while_running(tmp_path):
    assert system_module.System.description.parameter("window").to_dict()["fixed"] is True
    net = load(tmp_path, '<module class="System" name="S" window="5"/>')
    try:
        with pytest.raises(ValueError, match='"S.window" is fixed while the model runs'):
            net.set_parameter("S.window", 9)
        assert net.parameter("S.window") == 5
    finally:
        net.close()


def test_an_asynchronous_system_module_sees_the_lag_of_its_tick(tmp_path):
    net = load(tmp_path, '<module class="System" name="S" async="yes"/>', tick_duration="0.01")
    try:
        net.run(4, real_time=True)
        lag = float(net.output("S.LAG")[0])
        assert 0 < lag < 0.5                # its own copy of the clock carries the lag
    finally:
        net.close()


# --- Ikaros 3's outputs (IKAROS3-INTERFACES), as the class description reads them --------
def test_counts_state_and_progress(tmp_path):
    net = load(tmp_path, '<module class="System" name="S"/>'
                         '<module class="Constant" name="A" data="1"/>'
                         '<module class="Constant" name="B" data="2"/>'
                         '<module class="Scale" name="C"/>'
                         '<connection source="A.OUTPUT" target="C.INPUT"/>', stop="4")
    with net:
        assert net.output("S.MODULE_COUNT").tolist() == [4]
        assert net.output("S.CLASS_COUNT").tolist() == [3]       # System, Constant, Scale
        for k in range(1, 4):
            net.step()
            assert net.output("S.STATE").tolist() == [3]          # stepped from Python: play
            assert net.output("S.RUN_STATE").tolist() == [0, 0, 1, 0, 0]
            assert net.output("S.STOP_AFTER_KNOWN").tolist() == [1]
            assert net.output("S.PROGRESS")[0] == np.float32(k / 4)
            assert net.output("S.TICKS_PER_S") == net.output("S.TICKS_PER_SECOND")
            assert net.output("S.CPU_CORES") == net.output("S.CORES")


def test_without_stop_there_is_no_progress(tmp_path):
    with load(tmp_path, '<module class="System" name="S"/>') as net:
        net.step()
        assert net.output("S.STOP_AFTER_KNOWN").tolist() == [0]
        assert net.output("S.PROGRESS").tolist() == [0]


def test_real_time_mode_time_and_state(tmp_path):
    with load(tmp_path, '<module class="System" name="S"/>', tick_duration="0.01",
              dialect="2") as net:
        net.run(3, real_time=True)
        assert net.output("S.STATE").tolist() == [4]
        assert net.output("S.RUN_STATE").tolist() == [0, 0, 0, 1, 0]
        assert net.output("S.TIME") == net.output("S.REAL_TIME")
        assert net.output("S.NOMINAL_TIME")[0] == np.float32(2 * 0.01)
        net.step()
        assert net.output("S.TIME") == net.output("S.NOMINAL_TIME")


@pytest.mark.parametrize("duration", ["1e-9", "1000"])
def test_tick_time_usage_idle_ratio_and_overload(tmp_path, duration):
    with load(tmp_path, '<module class="System" name="S"/>', tick_duration=duration) as net:
        net.step()
        uptime = float(net.output("S.UPTIME")[0])
        spent = net.timing.last_spent               # the tick just completed
        net.step()
        assert net.output("S.TICK_TIME_USAGE")[0] == np.float32(spent)
        share = spent / float(duration)
        assert net.output("S.TIME_USAGE")[0] == pytest.approx(share, rel=1e-6)
        assert net.output("S.IDLE_RATIO")[0] == pytest.approx(max(0.0, 1 - share), rel=1e-6)
        assert net.output("S.OVERLOAD").tolist() == [float(spent > float(duration))]
        assert float(net.output("S.UPTIME")[0]) > uptime > 0


def test_actual_duration_is_the_time_between_tick_starts(tmp_path, monkeypatch):
    fake = FakeTime()
    monkeypatch.setattr(system_module, "time", fake)
    with load(tmp_path, '<module class="System" name="S"/>') as net:
        got = []
        for wall in (1.0, 1.5, 2.25):
            fake.wall = wall
            net.step()
            got.append(float(net.output("S.ACTUAL_DURATION")[0]))
        assert got == [0, 0.5, 0.75]
