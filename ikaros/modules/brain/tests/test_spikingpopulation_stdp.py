"""STDP of SpikingPopulation on a two-neuron pair, against the rule computed tick by tick."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body

A_PLUS, A_MINUS, TAU_PLUS, TAU_MINUS, W_MAX = 0.05, 0.06, 20.0, 10.0, 1.0


def pair(tmp_path, w0, pre_current, post_current, ticks, time_step=1.0):
    """Run the pair; returns the spikes of Pre, of Post and Post's weight after each tick."""
    net = load_body(
        tmp_path,
        f'<module class="Constant" name="A" data="{pre_current}"/>'
        f'<module class="Constant" name="B" data="{post_current}"/>'
        '<module class="SpikingPopulation" name="Pre" population_size="1"/>'
        '<module class="SpikingPopulation" name="Post" population_size="1" '
        f'spike_input="flag" excitation_weights="{w0}" stdp="yes" weights_output="yes" '
        f'stdp_a_plus="{A_PLUS}" stdp_a_minus="{A_MINUS}" stdp_tau_plus="{TAU_PLUS}" '
        f'stdp_tau_minus="{TAU_MINUS}" stdp_w_max="{W_MAX}" time_step="{time_step}"/>'
        '<connection source="A.OUTPUT" target="Pre.DIRECT_IN" delay="0"/>'
        '<connection source="B.OUTPUT" target="Post.DIRECT_IN" delay="0"/>'
        '<connection source="Pre.OUTPUT" target="Post.EXCITATION_IN" delay="1"/>')
    try:
        pre, post, w = [], [], []
        assert net.output("Post.EXCITATION_WEIGHTS").shape == (1, 1)
        for _ in range(ticks):
            net.step()
            pre.append(bool(net.output("Pre.OUTPUT")[0] >= 30))
            post.append(bool(net.output("Post.OUTPUT")[0] >= 30))
            w.append(float(net.output("Post.EXCITATION_WEIGHTS")[0, 0]))
        return pre, post, w
    finally:
        net.close()


def stdp_rule(w0, arrivals, post_spikes, dt):
    """The pair-based rule with traces, plain Python floats: every tick the traces decay by
    exp(-dt/tau); an arriving pre spike first lowers w by A- * y and then adds 1 to x; a post
    spike adds 1 to y and then raises w by A+ * x; w stays in 0..W_MAX."""
    w, x, y, out = w0, 0.0, 0.0, []
    for arrived, fired in zip(arrivals, post_spikes):
        x *= math.exp(-dt / TAU_PLUS)
        y *= math.exp(-dt / TAU_MINUS)
        if arrived:
            w = min(max(w - A_MINUS * y, 0.0), W_MAX)
            x += 1.0
        if fired:
            y += 1.0
            w = min(max(w + A_PLUS * x, 0.0), W_MAX)
        out.append(w)
    return out


@pytest.mark.parametrize("pre_current, post_current, time_step", [
    (10.0, 6.0, 1.0), (6.0, 12.0, 1.0), (8.0, 8.5, 0.5)])
def test_stdp_pair_follows_the_rule_tick_by_tick(tmp_path, pre_current, post_current,
                                                 time_step):
    w0 = 0.5
    pre, post, w = pair(tmp_path, w0, pre_current, post_current, 600, time_step)
    arrivals = [False] + pre[:-1]            # the connection delays Pre's spikes one tick
    expected = stdp_rule(w0, arrivals, post, time_step)
    assert sum(arrivals) > 3 and sum(post) > 3
    assert np.allclose(w, expected, rtol=0, atol=1e-5)
    steps = np.diff([w0] + w)
    assert np.any(steps > 1e-4) and np.any(steps < -1e-4)   # both potentiation and depression


def test_stdp_weights_stay_in_range(tmp_path):
    """Many pre-before-post pairs drive the weight up to stdp_w_max and no further."""
    _, _, w = pair(tmp_path, 0.9, 20.0, 9.0, 800)
    assert max(w) == pytest.approx(W_MAX) and min(w) >= 0.0
