"""Tests of the BackProp module."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

XOR_X = np.array([[0, 0], [0, 1], [1, 0], [1, 1]], float)
XOR_T = np.array([0, 1, 1, 0], float)


def xor_net(tmp_path, **params):
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    return load(tmp_path,
                '<module class="ListIterator" name="X" listdata="0 0; 0 1; 1 0; 1 1" '
                'repeat="yes"/>'
                '<module class="ListIterator" name="T" listdata="0; 1; 1; 0" repeat="yes"/>'
                f'<module class="BackProp" name="B" {attrs}/>'
                '<connection source="X.OUTPUT" target="B.INPUT" delay="0"/>'
                '<connection source="X.OUTPUT" target="B.T_INPUT" delay="0"/>'
                '<connection source="T.OUTPUT" target="B.T_TARGET" delay="0"/>')


def sweep(net):
    out = []
    for _ in range(4):
        net.step()
        out.append(float(net.output("B.OUTPUT")[0]))
    return np.array(out)


def sigmoid(x):
    return 1 / (1 + np.exp(-x))


def test_learns_xor_with_a_fixed_seed(tmp_path):
    net = xor_net(tmp_path, hidden_units=4, lr=0.5, momentum=0.9, seed=1)
    try:
        first = sweep(net)
        assert np.abs(first - XOR_T).max() > 0.3                  # not known at the start
        errors = []
        for _ in range(400):
            net.run(ticks=8)
            errors.append(float(net.output("B.ERROR")[0]))
        out = sweep(net)
        assert np.abs(out - XOR_T).max() < 0.1, out
        assert errors[-1] < 0.1 and errors[-1] < errors[0]
    finally:
        net.close()


def test_first_ticks_match_numpy(tmp_path):
    lr, momentum = 0.3, 0.5
    net = xor_net(tmp_path, hidden_units=3, lr=lr, momentum=momentum, seed=5)
    try:
        rng = np.random.default_rng(5)                       # the documented initial weights
        w1 = rng.uniform(-0.5, 0.5, (3, 3))
        w2 = rng.uniform(-0.5, 0.5, (1, 4))
        d1, d2 = np.zeros_like(w1), np.zeros_like(w2)
        for tick in range(12):
            x1 = np.append(XOR_X[tick % 4], 1)
            h = np.append(sigmoid(w1 @ x1), 1)
            y = sigmoid(w2 @ h)
            out = y                                # the response before the tick's step
            t = XOR_T[tick % 4]
            err = np.sqrt(np.sum((t - y) ** 2))    # a norm, as in Ikaros 2
            do = (t - y) * y * (1 - y)
            dh = (w2[:, :3].T @ do) * h[:3] * (1 - h[:3])
            d2 = lr * np.outer(do, h) + momentum * d2
            d1 = lr * np.outer(dh, x1) + momentum * d1
            w1, w2 = w1 + d1, w2 + d2
            net.step()
            assert net.output("B.ERROR")[0] == pytest.approx(err, rel=1e-5)
            assert net.output("B.OUTPUT")[0] == pytest.approx(out[0], rel=1e-5)
    finally:
        net.close()


def test_same_seed_same_run_and_output_size(tmp_path):
    runs = []
    for _ in range(2):
        net = xor_net(tmp_path, seed=9)
        try:
            assert net.output("B.OUTPUT").shape == (1,)
            assert net.output("B.ERROR").shape == (1,)
            runs.append(np.concatenate([sweep(net) for _ in range(5)]))
        finally:
            net.close()
    assert np.array_equal(runs[0], runs[1])


def test_several_outputs_and_separate_input(tmp_path):
    # learns x -> (x0 and x1, x0 or x1) on T_INPUT; INPUT shows a fixed pattern
    net = load(tmp_path,
               '<module class="ListIterator" name="X" listdata="0 0; 0 1; 1 0; 1 1" '
               'repeat="yes"/>'
               '<module class="ListIterator" name="T" listdata="0 0; 0 1; 0 1; 1 1" '
               'repeat="yes"/>'
               '<module class="Constant" name="Q" data="1 0"/>'
               '<module class="BackProp" name="B" lr="0.5" momentum="0.5" seed="2"/>'
               '<connection source="Q.OUTPUT" target="B.INPUT" delay="0"/>'
               '<connection source="X.OUTPUT" target="B.T_INPUT" delay="0"/>'
               '<connection source="T.OUTPUT" target="B.T_TARGET" delay="0"/>')
    try:
        assert net.output("B.OUTPUT").shape == (2,)
        net.run(ticks=3000)
        out = net.output("B.OUTPUT")
        assert out[0] < 0.1 and out[1] > 0.9
    finally:
        net.close()
