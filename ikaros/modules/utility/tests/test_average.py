"""Tests of the Average module."""
import numpy as np

from ikaros.testing import load_body as load

# A Sweep from 1 by 1 (max 100) connected with delay 0 gives x_k = k + 2 on tick k.
SWEEP = '<module class="Sweep" name="S" min="1" max="100" step="1" outputsize="2"/>\n'


def _load(tmp_path, attrs, source=SWEEP, name="S"):
    return load(tmp_path, source + f'<module class="Average" name="A" {attrs}/>\n'
                f'<connection source="{name}.OUTPUT" target="A.INPUT" delay="0"/>')


def _inputs(n):
    return np.arange(2, n + 2, dtype=np.float64)


def test_cumulative_average(tmp_path):
    net = _load(tmp_path, "")
    try:
        assert np.array_equal(net.output("A.OUTPUT"), [0, 0])
        xs = _inputs(8)
        for k in range(8):
            net.step()
            assert np.allclose(net.output("A.OUTPUT"), xs[:k + 1].mean())
    finally:
        net.close()


def test_simple_moving_average_over_the_samples_so_far(tmp_path):
    net = _load(tmp_path, 'type="SMA" window_size="3"')
    try:
        xs = _inputs(8)
        for k in range(8):
            net.step()
            assert np.allclose(net.output("A.OUTPUT"), xs[max(0, k - 2):k + 1].mean()), k
    finally:
        net.close()


def test_window_size_change_restarts_the_window(tmp_path):
    net = _load(tmp_path, 'type="SMA" window_size="3"')
    try:
        net.run(ticks=5)
        net.set_parameter("A.window_size", 2)
        xs = _inputs(9)
        for k in range(5, 9):
            net.step()
            assert np.allclose(net.output("A.OUTPUT"), xs[max(5, k - 1):k + 1].mean()), k
    finally:
        net.close()


def test_exponential_moving_average(tmp_path):
    net = _load(tmp_path, 'type="EMA" alpha="0.25"')
    try:
        y = 0.0
        for x in _inputs(8):
            net.step()
            y = 0.75 * y + 0.25 * x
            assert np.allclose(net.output("A.OUTPUT"), y)
    finally:
        net.close()


def test_root_mean_square(tmp_path):
    source = '<module class="Constant" name="C" data="-3 4"/>\n'
    net = _load(tmp_path, 'operation="sqr" sqrt="yes"', source, "C")
    try:
        net.run(ticks=3)
        assert np.allclose(net.output("A.OUTPUT"), [3, 4])
    finally:
        net.close()


def test_abs_operation(tmp_path):
    source = ('<module class="Sweep" name="W" min="-2" max="2" step="1"/>\n')
    net = _load(tmp_path, 'operation="abs"', source, "W")
    try:
        xs = []
        for _ in range(6):
            net.step()
            xs.append(abs(float(net.output("W.OUTPUT")[0])))
            assert np.isclose(net.output("A.OUTPUT")[0], np.mean(xs))
    finally:
        net.close()


def test_termination_criterion_stops_the_run(tmp_path):
    # EMA of 0 from an initial 0 output: |average| is 0 < 0.5 on tick 0.
    source = '<module class="Constant" name="C" data="0 10"/>\n'
    net = _load(tmp_path, 'type="EMA" termination_criterion="0.5" select="0"', source, "C")
    try:
        ticks = net.run(ticks=10)
        assert ticks == 1 and net.stopped
    finally:
        net.close()


def test_default_criterion_never_stops(tmp_path):
    source = '<module class="Constant" name="C" data="0 0"/>\n'
    net = _load(tmp_path, "", source, "C")
    try:
        assert net.run(ticks=10) == 10 and not net.stopped
    finally:
        net.close()


def test_ikaros_3_average_is_the_mean_of_all_elements(tmp_path):
    # dialect 3 (MODULES-V3 §5): one value, the mean of this tick's elements, not over time
    net = load(tmp_path, '<module class="Constant" name="C" data="3 1; 4 -2"/>'
                         '<module class="Average" name="A"/>'
                         '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>',
               dialect="3")
    try:
        for _ in range(3):
            net.step()
            out = net.output("A.OUTPUT")
            assert out.shape == (1,) and out[0] == 1.5
    finally:
        net.close()
