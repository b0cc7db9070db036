"""Tests of the EventTrigger module. Ikaros 2 (golden-v2 EventTrigger): events last duration
+ 1 ticks and pauses timeout + 1, the output is rand() % size with glibc's unseeded rand()
(1804289383, 846930886, 1681692777, ...: the C library's documented sequence for seed 1),
drawn again when it repeats the last event."""
import numpy as np

from ikaros.testing import load_body as load


def _trace(net, ticks):
    """The index of the output that is on at each tick, or -1."""
    trace = []
    for _ in range(ticks):
        net.step()
        out = net.output("E.OUTPUT")
        assert out.sum() in (0, 1) and set(np.unique(out)) <= {0, 1}
        trace.append(int(np.argmax(out)) if out.any() else -1)
    return trace


def _runs(trace):
    """(value, length) of each run of equal values."""
    runs = []
    for v in trace:
        if runs and runs[-1][0] == v:
            runs[-1][1] += 1
        else:
            runs.append([v, 1])
    return runs


GLIBC_SEED_1 = [1804289383, 846930886, 1681692777, 1714636915, 1957747793, 424238335,
                719885386, 1649760492, 596516649, 1189641421]


def test_ikaros_2_timing_and_choice(tmp_path):
    net = load(tmp_path, '<module class="EventTrigger" name="E" size="3" duration="2" '
               'timeout="1" initial_delay="1"/>')
    with net:
        draws = iter(GLIBC_SEED_1)
        events, last = [], -1
        for _ in range(4):
            k = next(draws) % 3
            while k == last:
                k = next(draws) % 3
            events.append(k)
            last = k
        want = [-1]
        for k in events:
            want += [k] * 3 + [-1] * 2          # duration + 1 on, timeout + 1 off
        assert _trace(net, len(want)) == want


def test_single_output_timing(tmp_path):
    net = load(tmp_path, '<module class="EventTrigger" name="E" duration="3" timeout="2" '
               'initial_delay="2" timing="exact"/>')
    try:
        assert not net.output("E.OUTPUT").any()
        assert _trace(net, 14) == [-1, -1, 0, 0, 0, -1, -1, 0, 0, 0, -1, -1, 0, 0]
    finally:
        net.close()


def test_no_timeout_means_back_to_back_events_that_never_repeat(tmp_path):
    net = load(tmp_path, '<module class="EventTrigger" name="E" size="3" duration="2" '
               'seed="11" timing="exact"/>')
    try:
        trace = _trace(net, 40)
        runs = _runs(trace)
        assert -1 not in trace
        # Events of 2 ticks each, a different output every time.
        assert all(length == 2 for _, length in runs[:-1])
        events = trace[::2]
        assert all(a != b for a, b in zip(events, events[1:]))
        assert set(events) == {0, 1, 2}
    finally:
        net.close()


def test_per_output_durations(tmp_path):
    net = load(tmp_path, '<module class="EventTrigger" name="E" size="2" duration="1 4" '
               'timeout="1" timing="exact"/>')
    try:
        for value, length in _runs(_trace(net, 30))[:-1]:
            assert length == {-1: 1, 0: 1, 1: 4}[value]
    finally:
        net.close()


def test_next_starts_a_new_event_at_once(tmp_path):
    # NEXT is 1 on ticks 3 and 4 (Sweep 0..5 thresholded by an Expression), else 0.
    net = load(tmp_path,
               '<module class="Sweep" name="S" min="0" max="100" step="1"/>\n'
               '<module class="Expression" name="N" expression="x == 4 or x == 5"/>\n'
               '<module class="EventTrigger" name="E" size="2" duration="100" seed="2"/>\n'
               '<connection source="S.OUTPUT" target="N.x" delay="0"/>\n'
               '<connection source="N.OUTPUT" target="E.NEXT" delay="0"/>')
    try:
        trace = _trace(net, 8)
        first = trace[0]
        assert trace[:3] == [first] * 3
        assert trace[3] == 1 - first and trace[4] == first       # switched on both ticks
        assert trace[5:] == [first] * 3
    finally:
        net.close()


def test_seed_repeats_the_run(tmp_path):
    body = '<module class="EventTrigger" name="E" size="4" duration="1" seed="9"/>'
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    nets = [load(tmp_path / "a", body), load(tmp_path / "b", body)]
    try:
        assert _trace(nets[0], 20) == _trace(nets[1], 20)
    finally:
        for net in nets:
            net.close()
