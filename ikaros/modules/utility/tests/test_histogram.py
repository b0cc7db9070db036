"""Tests of the Histogram module (Ikaros 2: only the first element is counted, golden-v2
Histogram)."""
import numpy as np

from ikaros.testing import load_body as load


def test_counts_the_first_or_every_element_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="20" min="-0.2" '
               'max="1.2" seed="4"/>'
               '<module class="Histogram" name="H" size="7" min="0" max="1" elements="all"/>'
               '<module class="Histogram" name="F" size="7" min="0" max="1"/>'
               '<connection source="R.OUTPUT" target="H.INPUT" delay="0"/>'
               '<connection source="R.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        expected, first = np.zeros(7), np.zeros(7)
        for _ in range(5):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            counts, _ = np.histogram(x[(x >= 0) & (x <= 1)], bins=7, range=(0, 1))
            expected += counts
            first += np.histogram(x[:1][(x[:1] >= 0) & (x[:1] <= 1)], bins=7, range=(0, 1))[0]
            assert np.array_equal(net.output("H.OUTPUT"), expected)
            assert np.array_equal(net.output("F.OUTPUT"), first)
    finally:
        net.close()


def test_hand_worked_bins_edges_and_outliers(tmp_path):
    data = "-1 0 0.24 0.25 0.5 0.99 1 2"
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
               '<module class="Histogram" name="I" size="4" elements="all"/>'
               '<module class="Histogram" name="K" size="4" ignore_outliers="no" '
               'elements="all"/>'
               '<connection source="C.OUTPUT" target="I.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="K.INPUT" delay="0"/>')
    try:
        assert np.array_equal(net.output("I.OUTPUT"), [0, 0, 0, 0])
        net.step()
        assert np.array_equal(net.output("I.OUTPUT"), [2, 1, 1, 2])    # max is in the last bin
        assert np.array_equal(net.output("K.OUTPUT"), [3, 1, 1, 3])
        net.step()
        assert np.array_equal(net.output("I.OUTPUT"), [4, 2, 2, 4])
        net.command("I", "reset")
        assert np.array_equal(net.output("I.OUTPUT"), [0, 0, 0, 0])
    finally:
        net.close()


def test_trig_enables_counting(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0.5"/>'
               '<module class="Sweep" name="T" min="0" max="1" step="1"/>'
               '<module class="Histogram" name="H" size="2"/>'
               '<connection source="C.OUTPUT" target="H.INPUT" delay="0"/>'
               '<connection source="T.OUTPUT" target="H.TRIG" delay="0"/>')
    try:
        got = []
        for _ in range(4):               # T: 1, 0, 1, 0
            net.step()
            got.append(float(net.output("H.OUTPUT")[1]))
        assert got == [1, 1, 2, 2]
    finally:
        net.close()


def test_min_equal_to_max_counts_nothing_and_warns_once(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1"/>'
               '<module class="Histogram" name="H" size="3" min="1" max="1"/>'
               '<connection source="C.OUTPUT" target="H.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("H.OUTPUT"), [0, 0, 0])
        assert sum("max equals min" in entry[3] for entry in net.log) == 1
    finally:
        net.close()
