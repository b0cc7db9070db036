"""Tests of the Autoassociator module."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def f(x, gain=1.0):
    return 1 / (1 + np.exp(-gain * x))


def row(v):
    return " ".join(f"{x:g}" for x in v)


def test_completes_a_stored_pattern_from_a_noisy_cue(tmp_path):
    rng = np.random.default_rng(4)
    n = 64
    patterns = (rng.random((3, n)) < 0.5).astype(int)
    net = load(tmp_path,
               f'<module class="ListIterator" name="P" listdata="{"; ".join(map(row, patterns))}"'
               ' repeat="yes"/>'
               f'<module class="Constant" name="Cue" data="{row(np.zeros(n))}"/>'
               '<module class="Constant" name="Gain" data="1"/>'
               '<module class="Constant" name="Reset" data="0"/>'
               '<module class="Autoassociator" name="A" learning_rate="0.02" '
               'depression_rate="0" noise_level="0.05" seed="1"/>'
               '<connection source="P.OUTPUT" target="A.T-INPUT" delay="0"/>'
               '<connection source="Cue.OUTPUT" target="A.INPUT" delay="0"/>'
               '<connection source="Gain.OUTPUT" target="A.LEARNING-GAIN" delay="0"/>'
               '<connection source="Reset.OUTPUT" target="A.RESET" delay="0"/>')
    try:
        net.run(ticks=30)                                  # each pattern seen 10 times
        W = net.output("A.W")
        B = 2 * patterns - 1
        expected = 0.02 * 10 * (B.T @ B)
        np.fill_diagonal(expected, 0)
        assert np.allclose(W, expected, atol=1e-4)          # the Hebbian weights
        net.set_parameter("Gain.data", "0")                 # recall: no more learning
        for k, p in enumerate(patterns):
            cue = p.copy()
            flip = rng.choice(n, 12, replace=False)         # 12 of 64 bits wrong
            cue[flip] = 1 - cue[flip]
            net.set_parameter("Cue.data", row(cue))
            net.set_parameter("Reset.data", "1")
            net.step()
            assert np.allclose(net.output("A.OUTPUT"), 0.5 + 0.1 * (f(net.output("A.NET"))
                                                                    - 0.5))
            net.set_parameter("Reset.data", "0")
            net.run(ticks=60)
            out = net.output("A.OUTPUT")
            assert np.array_equal(out > 0.5, p.astype(bool)), k
            assert np.abs(out - p).max() < 0.05
            v = 2 * out - 1
            assert net.output("A.ENERGY")[0] == pytest.approx(-0.5 * v @ W @ v, rel=1e-4)
        assert np.allclose(net.output("A.W"), W)            # gain 0: nothing learned
    finally:
        net.close()


def test_dynamics_and_depression_match_numpy(tmp_path):
    cue = np.array([1, 0, 0.5, 0, 1])
    target = np.array([1, 1, 0, 0, 1])
    top = np.array([0.2, -0.1, 0, 0.3, 0])
    err = np.array([1, 0, -1, 0, 2])
    net = load(tmp_path,
               f'<module class="Constant" name="Cue" data="{row(cue)}"/>'
               f'<module class="Constant" name="T" data="{row(target)}"/>'
               f'<module class="Constant" name="Top" data="{row(top)}"/>'
               f'<module class="Constant" name="Err" data="{row(err)}"/>'
               '<module class="Constant" name="G" data="0.5"/>'
               '<module class="Autoassociator" name="A" learning_rate="0.1" '
               'depression_rate="0.2" activation_gain="2" noise_level="0"/>'
               '<connection source="Cue.OUTPUT" target="A.INPUT" delay="0"/>'
               '<connection source="T.OUTPUT" target="A.T-INPUT" delay="0"/>'
               '<connection source="Top.OUTPUT" target="A.TOP-DOWN-INPUT" delay="0"/>'
               '<connection source="Err.OUTPUT" target="A.TOP-DOWN-ERROR" delay="0"/>'
               '<connection source="G.OUTPUT" target="A.ACTIVATION-GAIN" delay="0"/>')
    try:
        assert np.allclose(net.output("A.OUTPUT"), 0.5)       # the rest state
        n = 5
        W, D, s = np.zeros((n, n)), np.zeros((n, n)), np.full(n, 0.5)
        b = 2 * target - 1
        for tick in range(15):
            W += 0.1 * np.outer(b, b) * (1 - np.eye(n))
            net_in = (W * (1 - D)) @ (2 * s - 1) + cue + top
            s = s + 0.1 * (f(net_in, 2 * 0.5) - s)
            D += 0.2 * (np.abs(np.outer(2 * s - 1, 2 * s - 1)) - D)
            net.step()
            assert np.allclose(net.output("A.NET"), net_in, atol=1e-4), tick
            assert np.allclose(net.output("A.OUTPUT"), s, atol=1e-5), tick
            assert np.allclose(net.output("A.W_DEPRESSION"), D, atol=1e-5), tick
            assert np.allclose(net.output("A.W"), W, atol=1e-4), tick
            assert np.allclose(net.output("A.T-OUTPUT"), f(W @ b, 1.0), atol=1e-5)
            assert np.allclose(net.output("A.ERROR-OUTPUT"), W.T @ err, atol=1e-4)
        assert net.output("A.U").shape == (5, 0)             # no auxiliary input
        assert np.array_equal(net.output("A.AUX-OUTPUT"), np.zeros(5))
    finally:
        net.close()


def test_depression_weakens_a_held_pattern(tmp_path):
    p = np.array([1, 1, 0, 0, 1, 0])
    body = (f'<module class="Constant" name="T" data="{row(p)}"/>'
            f'<module class="Constant" name="Cue" data="{row(p)}"/>'
            '<module class="Autoassociator" name="A" learning_rate="0.5" noise_level="0" '
            'depression_rate="{}"/>'
            '<module class="Constant" name="G" data="1"/>'
            '<connection source="T.OUTPUT" target="A.T-INPUT" delay="0"/>'
            '<connection source="G.OUTPUT" target="A.LEARNING-GAIN" delay="0"/>'
            '<connection source="Cue.OUTPUT" target="A.INPUT" delay="0"/>')
    nets = [load(tmp_path, body.format(rate)) for rate in (0, 0.05)]
    try:
        for net in nets:
            net.run(ticks=4)
            net.set_parameter("G.data", "0")
            net.set_parameter("Cue.data", row(np.zeros(6)))
            net.run(ticks=300)
        plain, depressed = (net.output("A.OUTPUT") for net in nets)
        assert np.array_equal(plain > 0.9, p.astype(bool))      # the attractor holds
        assert np.abs(plain - 0.5).min() > 0.49
        assert np.abs(depressed - 0.5).max() < 0.45                # weakened by depression
        assert np.array_equal(depressed > 0.5, p.astype(bool))
        assert nets[1].output("A.W_DEPRESSION")[0, 1] > 0.5
        assert np.all(nets[0].output("A.W_DEPRESSION") == 0)
    finally:
        for net in nets:
            net.close()


def test_auxiliary_weights_are_learned_and_clipped(tmp_path):
    aux = np.array([1, 0, 1])
    p = np.array([0, 1, 1, 0])
    net = load(tmp_path,
               f'<module class="Constant" name="P" data="{row(p)}"/>'
               f'<module class="Constant" name="X" data="{row(aux)}"/>'
               '<module class="Constant" name="Z" data="0 0 0 0"/>'
               '<module class="Autoassociator" name="A" learning_rate="0.3" noise_level="0" '
               'depression_rate="0"/>'
               '<connection source="Z.OUTPUT" target="A.INPUT" delay="0"/>'
               '<connection source="P.OUTPUT" target="A.T-INPUT" delay="0"/>'
               '<connection source="X.OUTPUT" target="A.AUX-T-INPUT" delay="0"/>'
               '<connection source="X.OUTPUT" target="A.AUX-INPUT" delay="0"/>')
    try:
        assert net.output("A.U").shape == (4, 3)
        net.step()
        U = 0.3 * np.outer(2 * p - 1, 2 * aux - 1)
        assert np.allclose(net.output("A.U"), U)
        assert np.allclose(net.output("A.AUX-OUTPUT"), f(U @ (2 * aux - 1)))
        net.run(ticks=5)
        assert np.allclose(net.output("A.U"), np.outer(2 * p - 1, 2 * aux - 1))   # clipped
    finally:
        net.close()
