"""Tests of the LeakyIntegrator module (Ikaros 3, MODULES-V3 §8)."""
import pytest

from ikaros.testing import load_body as load


def _run(tmp_path, attrs, e="1, 0.5", i="0.25", ticks=4, tick_duration="1"):
    net = load(tmp_path, f'<module class="Constant" name="E" data="{e}"/>'
                         f'<module class="Constant" name="I" data="{i}"/>'
                         f'<module class="LeakyIntegrator" name="L" {attrs}/>'
                         '<connection source="E.OUTPUT" target="L.EXCITATION" delay="0"/>'
                         '<connection source="I.OUTPUT" target="L.INHIBITION" delay="0"/>',
               tick_duration=tick_duration)
    try:
        out = []
        for _ in range(ticks):
            net.step()
            out.append(float(net.output("L.OUTPUT")[0]))
        return out
    finally:
        net.close()


def test_sums_with_gains_and_never_goes_below_zero(tmp_path):
    assert _run(tmp_path, 'excitation_gain="2" inhibition_gain="4"') == \
        pytest.approx([2, 4, 6, 8])                    # 2*1.5 - 4*0.25 = 2 per tick
    assert _run(tmp_path, "", e="0.1", i="1, 1") == [0, 0, 0, 0]


def test_linear_and_exponential_decay_per_second(tmp_path):
    # linear: x = x + 1.25 - 0.5*0.5; exponential: x = (x + 1.25) * (1 - 0.5*0.5)
    assert _run(tmp_path, 'decay_type="linear" decay_rate="0.5"', tick_duration="0.5") == \
        pytest.approx([1.0, 2.0, 3.0, 4.0])
    expected, x = [], 0.0
    for _ in range(4):
        x = (x + 1.25) * 0.75
        expected.append(x)
    assert _run(tmp_path, 'decay_type="exponential" decay_rate="0.5"',
                tick_duration="0.5") == pytest.approx(expected)
