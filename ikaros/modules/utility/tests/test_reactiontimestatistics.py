"""Tests of the ReactionTimeStatistics module: counting="corrected" (this project's), and the
original's counting (golden-v2 ReactionTimeStatistics: outliers counted twice in
CHOICE-COUNT, times from tick 0 before the first start)."""

import numpy as np
import pytest

from ikaros.module import WARNING
from ikaros.testing import load_body as load

# tick: START, STOP (3 channels)
LINES = """START/1 STOP/3
0  0 0 1
1  0 0 0
0  0 0 0
0  0 1 0
1  0 0 0
0  1 0 0
0  0 0 1
1  1 0 0
0  0 3 2
0  0 0 0
0  0 0 0
0  0 0 0
0  0 0 1
"""
# tick 0: a response before any start is ignored; tick 1: start; tick 3: channel 1 after 2
# ticks; tick 4: start; 5: channel 0 after 1; 6: channel 2 after 2; 7: channel 0 after 3,
# then a new start; 8: channel 1 (the largest) after 1; 12: channel 2 after 5 (an outlier).


def model(tmp_path, attrs='bins="4" max_rt="4" counting="corrected"'):
    (tmp_path / "rt.txt").write_text(LINES)
    return load(tmp_path, '<module class="InputFile" name="F" filename="rt.txt" '
                          'send_end_of_file="no"/>'
                          f'<module class="ReactionTimeStatistics" name="R" {attrs}/>'
                          '<connection source="F.START" target="R.START" delay="0"/>'
                          '<connection source="F.STOP" target="R.STOP" delay="0"/>')


def simulate(rows, bins, max_rt, original=False):
    """A plain re-statement of the rules, one tick at a time."""
    hist = np.zeros((bins, 3))
    outlier, count, total = np.zeros(3), np.zeros(3), np.zeros(3)
    rt, started, balance, last = 0, original, 0, 0
    for start, stop in rows:
        if started and max(stop) > 0:
            c = int(np.argmax(stop))
            b = int(np.floor(rt * bins / max_rt))
            if 0 <= b < bins:
                hist[b, c] += 1
            elif original:
                count[c] += 1
            else:
                outlier[c] += 1
            count[c] += 1
            total[c] += rt
            balance -= 1
            last = rt
        if start > 0:
            rt, started = 0, True
            balance += 1
        rt += 1
    mean = np.where(count > 0, total / np.maximum(count, 1), 0)
    return hist, outlier, count, mean, balance, last


def test_hand_worked(tmp_path):
    net = model(tmp_path)
    try:
        net.run(ticks=13)
        assert net.output("R.RT-HISTOGRAM").shape == (4, 3)
        expected = np.zeros((4, 3))
        for rt, c in [(2, 1), (1, 0), (2, 2), (3, 0), (1, 1)]:
            expected[rt, c] += 1
        assert np.array_equal(net.output("R.RT-HISTOGRAM"), expected)
        assert np.array_equal(net.output("R.RT-OUTLIER"), [0, 0, 1])
        assert np.array_equal(net.output("R.CHOICE-COUNT"), [2, 2, 2])
        assert np.allclose(net.output("R.CHOICE-PROBABILITY"), [1 / 3] * 3)
        assert np.allclose(net.output("R.RT-MEAN"), [2, 1.5, 3.5])
        assert net.output("R.STARTBALANCE")[0] == -3
        assert net.output("R.REACTIONTIME")[0] == 5
    finally:
        net.close()


@pytest.mark.parametrize("counting", ["original", "corrected"])
def test_every_tick_matches_a_simulation(tmp_path, counting):
    rows = [(float(r[0]), [float(v) for v in r[1:]])
            for r in (line.split() for line in LINES.splitlines()[1:])]
    net = model(tmp_path, f'bins="5" max_rt="3" counting="{counting}"')
    try:
        for tick in range(len(rows)):
            net.step()
            hist, outlier, count, mean, balance, last = simulate(
                rows[:tick + 1], 5, 3, original=counting == "original")
            assert np.array_equal(net.output("R.RT-HISTOGRAM"), hist), tick
            assert np.array_equal(net.output("R.RT-OUTLIER"), outlier), tick
            assert np.array_equal(net.output("R.CHOICE-COUNT"), count), tick
            assert np.allclose(net.output("R.RT-MEAN"), mean), tick
            p = count / count.sum() if count.sum() else np.zeros(3)
            assert np.allclose(net.output("R.CHOICE-PROBABILITY"), p), tick
            assert net.output("R.STARTBALANCE")[0] == balance, tick
            assert net.output("R.REACTIONTIME")[0] == last, tick
    finally:
        net.close()


def test_reset_clears_the_statistics(tmp_path):
    net = model(tmp_path)
    try:
        net.run(ticks=9)
        assert net.output("R.CHOICE-COUNT").sum() == 5
        net.command("R", "reset")
        net.run(ticks=4)                       # tick 12: channel 2 after 5 ticks
        assert np.array_equal(net.output("R.CHOICE-COUNT"), [0, 0, 1])
        assert np.array_equal(net.output("R.RT-HISTOGRAM"), np.zeros((4, 3)))
        assert np.array_equal(net.output("R.RT-OUTLIER"), [0, 0, 1])
        assert np.allclose(net.output("R.RT-MEAN"), [0, 0, 5])
    finally:
        net.close()


def test_max_rt_zero_makes_outliers_with_one_warning(tmp_path):
    net = model(tmp_path, 'bins="4" max_rt="0" counting="corrected"')
    try:
        net.run(ticks=13)
        assert np.array_equal(net.output("R.RT-OUTLIER"), [2, 2, 2])
        assert net.output("R.RT-HISTOGRAM").sum() == 0
        assert len([e for e in net.log if e[1] == WARNING]) == 1
    finally:
        net.close()


def test_original_histogram_has_a_column_per_column_of_a_matrix_stop(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1"/>'
                         '<module class="Constant" name="S" data="0 0; 0 1"/>'
                         '<module class="ReactionTimeStatistics" name="R" bins="3" '
                         'max_rt="3"/>'
                         '<connection source="A.OUTPUT" target="R.START" delay="0"/>'
                         '<connection source="S.OUTPUT" target="R.STOP" delay="0"/>')
    with net:
        net.run(ticks=3)          # three responses of channel 3 (row-major), rt 0, 1, 1
        hist = net.output("R.RT-HISTOGRAM")
        assert hist.shape == (3, 2)
        want = np.zeros(6)
        want[0 * 2 + 3] += 1      # bin 0 of channel 3: element 3 of the histogram
        want[1 * 2 + 3] += 2      # bin 1: element 5
        assert np.array_equal(hist.reshape(-1), want)
        assert np.array_equal(net.output("R.CHOICE-COUNT"), [[0, 0], [0, 3]])
