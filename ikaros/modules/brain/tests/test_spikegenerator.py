"""Tests of the SpikeGenerator module (Ikaros 3)."""
import numpy as np

from ikaros.testing import load_body as load


def _run(tmp_path, body, ticks, outputs=("SPIKES", "PHASE"), tick_duration="0.1"):
    net = load(tmp_path, body, tick_duration=tick_duration)
    try:
        got = {k: [] for k in outputs}
        for _ in range(ticks):
            net.step()
            for k in outputs:
                got[k].append(net.output(f"G.{k}").tolist())
        return got
    finally:
        net.close()


def test_regular_phase_grows_by_rate_times_tick_duration(tmp_path):
    got = _run(tmp_path, '<module class="SpikeGenerator" name="G" mode="regular" '
                         'firing_rate="4" initial_phase="0.25" population_size="2"/>', 8,
               outputs=("SPIKES", "PHASE", "FIRING_RATE", "EFFECTIVE_RATE"))
    phase, spikes, phases = np.float32(0.25), [], []
    for _ in range(8):
        phase = np.float32(phase + np.float32(4) * np.float32(0.1))
        fired = np.floor(phase)
        phase = np.float32(phase - fired)
        spikes.append([float(fired > 0)] * 2)
        phases.append([float(phase)] * 2)
    assert got["SPIKES"] == spikes and sum(s[0] for s in spikes) == 3
    assert np.allclose(got["PHASE"], phases)
    assert got["FIRING_RATE"] == [[10 * s[0]] * 2 for s in spikes]
    assert got["EFFECTIVE_RATE"] == [[4, 4]] * 8


def test_triggered_rising_edge_level_and_enable(tmp_path):
    (tmp_path / "t.txt").write_text("T/3\n1 1 1\n1 1 1\n0 0 0\n1 1 1\n")
    body = ('<module class="InputFile" name="F" filename="t.txt"/>'
            '<module class="Constant" name="E" data="1 1 0"/>'
            '<module class="SpikeGenerator" name="G" mode="triggered" population_size="3" '
            '{attrs}/>'
            '<connection source="F.T" target="G.TRIGGER" delay="0"/>'
            '<connection source="E.OUTPUT" target="G.ENABLE" delay="0"/>')
    edge = _run(tmp_path, body.format(attrs=""), 4)["SPIKES"]
    assert [s[0] for s in edge] == [1, 0, 0, 1] and [s[2] for s in edge] == [0, 0, 0, 0]
    level = _run(tmp_path, body.format(attrs='trigger_mode="level"'), 4)["SPIKES"]
    assert [s[1] for s in level] == [1, 1, 0, 1]


def test_poisson_with_a_seed_repeats_and_keeps_the_refractory_period(tmp_path):
    body = ('<module class="SpikeGenerator" name="G" population_size="50" firing_rate="5" '
            'seed="7" refractory_period="0.25"/>')
    first = _run(tmp_path, body, 30, outputs=("SPIKES",))["SPIKES"]
    assert first == _run(tmp_path, body, 30, outputs=("SPIKES",))["SPIKES"]
    trains = np.array(first)
    assert 0 < trains.sum() < trains.size
    for unit in trains.T:                   # 0.25 s = 2.5 ticks: spikes at least 3 ticks apart
        times = np.flatnonzero(unit)
        assert np.all(np.diff(times) >= 3)
