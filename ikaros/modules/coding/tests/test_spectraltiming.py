"""Tests of the SpectralTiming module."""
import numpy as np

from ikaros.testing import load_body as load


def test_trace_and_taps_over_ticks(tmp_path):
    # a pulse train: Randomizer values above 0.7 count as stimuli
    body = ('<module class="Randomizer" name="R" outputsize="3" seed="12"/>\n'
            '<module class="Threshold" name="T" threshold="0.7"/>\n'
            '<module class="SpectralTiming" name="S" no_of_taps="4" sigma="0.1" '
            'decay="0.8"/>\n'
            '<connection source="R.OUTPUT" target="T.INPUT" delay="0"/>\n'
            '<connection source="T.OUTPUT" target="S.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        assert net.output("S.OUTPUT").shape == (4, 3)
        assert net.output("S.TRACE").shape == (3,)
        trace = np.zeros(3, dtype=np.float32)
        levels = np.arange(1, 5)[:, None] / 4
        for _ in range(12):
            net.step()
            x = net.output("T.OUTPUT")
            trace = np.maximum(trace * np.float32(0.8), x)
            assert np.allclose(net.output("S.TRACE"), trace, atol=1e-6)
            expected = trace * np.exp(-(trace - levels) ** 2 / (2 * 0.1 ** 2))
            assert np.allclose(net.output("S.OUTPUT"), expected, atol=1e-6)
    finally:
        net.close()


def test_hand_worked_single_pulse(tmp_path):
    # a pulse of 1 on tick 0 only, read from a file
    body = ('<module class="InputFile" name="F" filename="pulse.txt"/>\n'
            '<module class="SpectralTiming" name="S" no_of_taps="2" sigma="0.25" '
            'decay="0.5"/>\n'
            '<connection source="F.X" target="S.INPUT" delay="0"/>')
    (tmp_path / "pulse.txt").write_text("X/1\n1\n0\n0\n")
    net = load(tmp_path, body)
    try:
        net.step()          # trace 1: unit 1 (level 1) = 1, unit 0 (level 0.5) = e^-2
        assert np.allclose(net.output("S.OUTPUT"), [[np.exp(-2)], [1]])
        net.step()          # trace 0.5: unit 0 = 0.5, unit 1 = 0.5 e^-2
        assert np.allclose(net.output("S.OUTPUT"), [[0.5], [0.5 * np.exp(-2)]])
        net.step()          # trace 0.25
        assert np.allclose(net.output("S.TRACE"), [0.25])
        assert np.allclose(net.output("S.OUTPUT"),
                           [[0.25 * np.exp(-0.5)], [0.25 * np.exp(-4.5)]])
    finally:
        net.close()


def test_sigma_0_gives_zero_output_but_a_trace(tmp_path):
    body = ('<module class="Constant" name="K" data="0.5 1"/>\n'
            '<module class="SpectralTiming" name="S" sigma="0" no_of_taps="1"/>\n'
            '<connection source="K.OUTPUT" target="S.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("S.OUTPUT"), np.zeros((1, 2)))
        assert np.array_equal(net.output("S.TRACE"), np.float32([0.5, 1]))
        net.set_parameter("S.sigma", 0.5)       # one tap, tuned to level 1
        net.step()
        assert np.allclose(net.output("S.OUTPUT"), [[0.5 * np.exp(-0.5), 1]])
    finally:
        net.close()
