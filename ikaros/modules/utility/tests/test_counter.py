"""Tests of the Counter module (Ikaros 2: PERCENT is a fraction and both of its modes count
ticks, golden-v2 Counter)."""

import pytest

from ikaros.testing import load_body as load



# Sweep 0..3 step 1 gives 1, 2, 3, 0, 1, 2, 3, 0 on ticks 0..7.
RAMP = ('<module class="Sweep" name="W" min="0" max="3" step="1"/>\n'
        '<connection source="W.OUTPUT" target="N.INPUT" delay="0"/>\n')


def run(net, ticks):
    counts, percents = [], []
    for _ in range(ticks):
        net.step()
        counts.append(float(net.output("N.COUNT")[0]))
        percents.append(float(net.output("N.PERCENT")[0]))
    return counts, percents


def test_any_counts_ticks_above_threshold(tmp_path):
    net = load(tmp_path, RAMP + '<module class="Counter" name="N" mode="any" threshold="1.5"/>')
    try:
        assert net.output("N.COUNT").shape == (1,) and net.output("N.PERCENT").shape == (1,)
        counts, percents = run(net, 8)
        assert counts == [0, 1, 2, 2, 2, 3, 4, 4]
        expected = [c / (t + 1) for t, c in enumerate(counts)]
        assert percents == pytest.approx(expected, rel=1e-6)
    finally:
        net.close()


def test_elements_counts_each_element_and_component_counts_ticks(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="0.2 0.7; 0.9 0.5"/>\n'
               '<module class="Counter" name="N" mode="elements" threshold="0.5"/>\n'
               '<module class="Counter" name="A" threshold="0.5"/>\n'     # component
               '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>')
    try:
        counts, percents = run(net, 3)
        assert counts == [2, 4, 6]                   # 0.5 is not above 0.5
        assert percents == pytest.approx([0.5, 0.5, 0.5])
        assert net.output("A.COUNT")[0] == 3 and net.output("A.PERCENT")[0] == 1
    finally:
        net.close()


def test_count_interval_and_reset(tmp_path):
    net = load(tmp_path, RAMP + '<module class="Counter" name="N" mode="any" threshold="1.5" '
                                'count_interval="2" reset_interval="4"/>')
    try:
        counts, percents = run(net, 8)
        # counted ticks 0, 2 | reset at 4 | counted ticks 4, 6 (values 1, 3, 1, 3)
        assert counts == [0, 0, 1, 1, 0, 0, 1, 1]
        assert percents == pytest.approx([0, 0, 0.5, 0.5, 0, 0, 0.5, 0.5])
    finally:
        net.close()


def test_prints_every_print_interval(tmp_path):
    net = load(tmp_path, RAMP + '<module class="Counter" name="N" mode="any" threshold="1.5" '
                                'print_interval="3"/>')
    try:
        net.run(ticks=7)
        printed = [(tick, message) for tick, _level, where, message in net.log
                   if where.split(".")[-1] == "N"]
        assert printed == [(2, "count 2 (66.67%) at tick 2"), (5, "count 3 (50.00%) at tick 5")]
    finally:
        net.close()


def test_the_default_threshold_is_0(tmp_path):
    # golden-v2 Counter "varying": 0.24 is counted, -0.73 is not
    net = load(tmp_path, '<module class="Constant" name="C" data="0.24"/>\n'
                         '<module class="Constant" name="D" data="-0.73 0"/>\n'
                         '<module class="Counter" name="N"/>\n'
                         '<module class="Counter" name="M"/>\n'
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>\n'
                         '<connection source="D.OUTPUT" target="M.INPUT" delay="0"/>')
    with net:
        net.run(ticks=2)
        assert net.output("N.COUNT")[0] == 2 and net.output("M.COUNT")[0] == 0
