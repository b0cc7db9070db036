"""Tests of ValueAccumulator: the race, choices and statistics, worked by hand."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def build(params, index="1 0", evidence="0.25"):
    return (f'<module class="Constant" name="I" data="{index}"/>'
            f'<module class="Constant" name="X" data="{evidence}"/>'
            f'<module class="ValueAccumulator" name="V" {params}/>'
            '<connection source="I.OUTPUT" target="V.INDEX" delay="0"/>'
            '<connection source="X.OUTPUT" target="V.INPUT" delay="0"/>')


def reference(ticks, index, e, alpha=0.2, beta=0.2, gamma=0.0, delta=0.0, lam=0.0):
    index = np.asarray(index, float)
    s = np.zeros(index.size)
    states, choices = [], []
    for _ in range(ticks):
        s = (1 - lam) * s + alpha * index * e - beta * (1 - index) * e + gamma * s
        s = s - delta * (s.sum() - s)
        s = np.clip(s, 0, 1)
        if s.max() >= 1:
            choices.append(int(np.argmax(s)))
            s = np.zeros_like(s)
        else:
            choices.append(None)
        states.append(s.copy())
    return states, choices


def test_race_and_statistics(tmp_path):
    net = load(tmp_path, build('alpha="0.5"', "1 0 0", "0.5 0.5"))   # E = 1
    try:
        states, choices = reference(9, [1, 0, 0], 1.0, alpha=0.5)
        for t in range(9):
            net.step()
            assert np.allclose(net.output("V.STATE"), states[t])
            chosen = net.output("V.CHOICE")
            assert np.array_equal(net.output("V.OUTPUT"), chosen)
            if choices[t] is None:
                assert chosen.sum() == 0
            else:
                assert chosen.tolist() == [1, 0, 0]
        # state 0.5, 1 -> choice on ticks 1, 3, 5, 7 after 1 tick of waiting each time
        assert choices == [None, 0, None, 0, None, 0, None, 0, None]
        assert net.output("V.CHOICE-COUNT").tolist() == [4, 0, 0]
        assert net.output("V.CHOICE-PROBABILITY").tolist() == [1, 0, 0]
        assert net.output("V.RT-MEAN").tolist() == [1, 0, 0]
        hist = net.output("V.RT-HISTOGRAM")
        assert hist.shape == (40, 3) and hist[0, 0] == 4 and hist.sum() == 4
        net.command("V", "reset")
        assert net.output("V.CHOICE-COUNT").sum() == 0 and net.output("V.RT-HISTOGRAM").sum() == 0
    finally:
        net.close()


def test_leak_feedback_and_lateral_inhibition(tmp_path):
    params = 'alpha="0.3" beta="0.1" gamma="0.05" delta="0.2" lambda="0.1"'
    net = load(tmp_path, build(params, "0 1 0.5", "0.4"))
    try:
        states, choices = reference(25, [0, 1, 0.5], 0.4, 0.3, 0.1, 0.05, 0.2, 0.1)
        for t in range(25):
            net.step()
            assert np.allclose(net.output("V.STATE"), states[t], atol=1e-6), t
        assert any(c is not None for c in choices)
    finally:
        net.close()


def test_leak_prevents_a_choice(tmp_path):
    # s = 0.9 s + 0.05 approaches 0.5 and never reaches 1
    net = load(tmp_path, build('alpha="0.2" lambda="0.1"', "1 0", "0.25"))
    try:
        net.run(ticks=200)
        assert net.output("V.STATE")[0] == pytest.approx(0.5, abs=1e-4)
        assert net.output("V.CHOICE-COUNT").sum() == 0
        assert np.all(net.output("V.RT-MEAN") == 0)          # no choices: 0, not NaN
    finally:
        net.close()


def test_noise_is_seeded_and_breaks_ties(tmp_path):
    def run(seed):
        net = load(tmp_path, build(f'alpha="0.1" beta="0" sigma="0.05" seed="{seed}"',
                                   "1 1", "0.1"))
        try:
            net.run(ticks=3000)
            return net.output("V.CHOICE-PROBABILITY").copy()
        finally:
            net.close()
    a, b = run(1), run(1)
    assert np.array_equal(a, b)
    assert a.sum() == pytest.approx(1) and np.all(np.abs(a - 0.5) < 0.15)


def test_positive_evidence_matrix_options_and_choice_ix(tmp_path):
    """golden-v2 ValueAccumulator: E sums only the positive elements of INPUT, a matrix
    INDEX keeps its shape, CHOICE_IX holds the last choice, and a choice's histogram cell
    is its flat index from the start of its row."""
    net = load(tmp_path, build("", "0 0 0; 0 0 1", "2 -5 0.5"))  # E = 2.5: s = 0.5 E (2 i - 1)
    try:
        net.step()                       # option 5 (row 1, column 2): 0.2 * 2.5 = 0.5
        assert net.output("V.STATE").shape == (2, 3)
        assert net.output("V.STATE").tolist() == [[0, 0, 0], [0, 0, 0.5]]
        assert net.output("V.CHOICE_IX")[0] == 0
        net.step()                       # 1.0: chosen after 1 tick
        assert net.output("V.CHOICE").tolist() == [[0, 0, 0], [0, 0, 1]]
        assert net.output("V.CHOICE_IX")[0] == 5
        hist = net.output("V.RT-HISTOGRAM")
        assert hist.shape == (40, 3) and hist[1, 2] == 1 and hist.sum() == 1   # 0 * 3 + 5
        net.step()
        assert net.output("V.CHOICE_IX")[0] == 5 and net.output("V.CHOICE").sum() == 0
    finally:
        net.close()
