"""Tests of the LinearAssociator module."""
import numpy as np

from ikaros.testing import load_body

W_TRUE = np.array([[0.5, -1.0, 2.0],
                   [1.5, 0.25, -0.5]])


def data_file(tmp_path, xs, ys, qs, learning=None):
    header = "X/3 Y/2 Q/3" + (" L/1" if learning is not None else "")
    lines = [header]
    for i, (x, y, q) in enumerate(zip(xs, ys, qs)):
        row = list(x) + list(y) + list(q) + ([learning[i]] if learning is not None else [])
        lines.append(" ".join(f"{v:.7g}" for v in row))
    (tmp_path / "data.txt").write_text("\n".join(lines) + "\n")


def model(attrs, learning=False):
    body = ('<module class="InputFile" name="F" filename="data.txt"/>'
            f'<module class="LinearAssociator" name="A" {attrs}/>'
            '<connection source="F.X" target="A.T-INPUT" delay="0"/>'
            '<connection source="F.Y" target="A.T-OUTPUT" delay="0"/>'
            '<connection source="F.Q" target="A.INPUT" delay="0"/>')
    if learning:
        body += '<connection source="F.L" target="A.LEARNING" delay="0"/>'
    return body


def test_gradient_descent_learns_a_linear_map(tmp_path):
    rng = np.random.default_rng(0)
    xs = rng.uniform(-1, 1, (400, 3))
    qs = rng.uniform(-1, 1, (400, 3))
    data_file(tmp_path, xs, xs @ W_TRUE.T, qs)
    net = load_body(tmp_path, model('alpha="0.3"'))
    try:
        assert net.output("A.MATRIX").shape == (2, 3)
        assert net.output("A.OUTPUT").shape == (2,)
        errors = []
        for _ in range(400):
            net.step()
            errors.append(net.output("A.ERROR")[0])
        np.testing.assert_allclose(net.output("A.MATRIX"), W_TRUE, atol=1e-3)
        np.testing.assert_allclose(net.output("A.OUTPUT"), W_TRUE @ qs[-1], atol=1e-3)
        assert errors[0] > 0.5 and errors[-1] < 1e-3
        np.testing.assert_allclose(net.output("A.CONFIDENCE"), 1 - errors[-1], atol=1e-6)
    finally:
        net.close()


def reference_gd(xs, ys, alpha, beta, passes):
    """Plain NumPy gradient descent with momentum: each tick one step on the tick's pair,
    then ``passes`` passes over a memory that never fills up."""
    w, m = np.zeros((2, 3)), np.zeros(2)
    out = []
    for t in range(len(xs)):
        for samples in [[(xs[t], ys[t])]] + [list(zip(xs[:t + 1], ys[:t + 1]))] * passes:
            norms = []
            for x, y in samples:
                e = y - w @ x
                norms.append(np.linalg.norm(e))
                m = beta * m + (1 - beta) * e
                w = w + alpha * np.outer(m, x)
        out.append((w.copy(), np.mean(norms)))
    return out


def test_momentum_memory_and_passes_follow_the_formula(tmp_path):
    rng = np.random.default_rng(1)
    xs = rng.uniform(-1, 1, (5, 3))
    ys = rng.uniform(-1, 1, (5, 2))
    data_file(tmp_path, xs, ys, xs)
    net = load_body(tmp_path, model('alpha="0.2" beta="0.5" memory_max="5" '
                                    'memory_training="3"'))
    try:
        for w, error in reference_gd(xs, ys, 0.2, 0.5, 3):
            net.step()
            np.testing.assert_allclose(net.output("A.MATRIX"), w, rtol=1e-4, atol=1e-6)
            np.testing.assert_allclose(net.output("A.ERROR")[0], error, rtol=1e-4)
    finally:
        net.close()


def test_lms_mode_solves_least_squares(tmp_path):
    rng = np.random.default_rng(2)
    xs = rng.uniform(-1, 1, (6, 3))
    ys = xs @ W_TRUE.T
    qs = rng.uniform(-1, 1, (6, 3))
    data_file(tmp_path, xs, ys, qs)
    net = load_body(tmp_path, model('mode="LMS" memory_max="20"'))
    try:
        net.step()
        net.step()          # two samples for three unknowns: the least-norm solution
        least_norm = np.linalg.pinv(xs[:2]) @ ys[:2]
        np.testing.assert_allclose(net.output("A.MATRIX"), least_norm.T, atol=1e-5)
        assert net.output("A.ERROR")[0] < 1e-5
        net.step()          # three independent samples fix the map
        np.testing.assert_allclose(net.output("A.MATRIX"), W_TRUE, atol=1e-4)
        np.testing.assert_allclose(net.output("A.OUTPUT"), W_TRUE @ qs[2], atol=1e-4)
    finally:
        net.close()


def test_learning_input_gates_and_scales_learning_with_use_learning(tmp_path):
    # x = (1, 0, 0), target (1, 2): each step multiplies the error by 1 - rate, and a tick
    # takes two steps (the tick's pair, then the memory of one sample)
    xs = np.array([[1, 0, 0]] * 4)
    ys = np.array([[1, 2]] * 4)
    data_file(tmp_path, xs, ys, xs, learning=[0, 0.5, 0, 1])
    net = load_body(tmp_path, model('alpha="0.5" use_learning="yes"', learning=True))
    try:
        net.step()          # LEARNING 0: nothing happens
        np.testing.assert_array_equal(net.output("A.MATRIX"), np.zeros((2, 3)))
        net.step()          # rate 0.5 * 0.5: the error becomes 0.75², met at 0.75 in the pass
        np.testing.assert_allclose(net.output("A.MATRIX")[:, 0], [0.4375, 0.875])
        np.testing.assert_allclose(net.output("A.ERROR"), [0.75 * np.sqrt(5)], rtol=1e-6)
        net.step()          # LEARNING 0 again: ERROR keeps its value, OUTPUT is computed
        np.testing.assert_allclose(net.output("A.MATRIX")[:, 0], [0.4375, 0.875])
        np.testing.assert_allclose(net.output("A.OUTPUT"), [0.4375, 0.875])
        np.testing.assert_allclose(net.output("A.ERROR"), [0.75 * np.sqrt(5)], rtol=1e-6)
        net.step()          # rate 0.5: the error 0.5625 (1, 2) falls to a quarter
        np.testing.assert_allclose(net.output("A.MATRIX")[:, 0], [0.859375, 1.71875])
    finally:
        net.close()


def test_ikaros_2_ignores_the_learning_input(tmp_path):
    # golden-v2 LinearAssociator: LEARNING below 0 or 0 does not stop learning
    xs = np.array([[1, 0, 0]] * 2)
    ys = np.array([[1, 2]] * 2)
    data_file(tmp_path, xs, ys, xs, learning=[0, -1])
    net = load_body(tmp_path, model('alpha="0.5"', learning=True))
    try:
        net.step()          # two steps of rate 0.5: the error is a quarter
        np.testing.assert_allclose(net.output("A.MATRIX")[:, 0], [0.75, 1.5])
        np.testing.assert_allclose(net.output("A.ERROR"), [0.5 * np.sqrt(5)], rtol=1e-6)
        net.step()
        np.testing.assert_allclose(net.output("A.MATRIX")[:, 0], [0.9375, 1.875])
    finally:
        net.close()


def test_full_memory_replaces_samples_reproducibly(tmp_path):
    rng = np.random.default_rng(3)
    xs = rng.uniform(-1, 1, (30, 3))
    data_file(tmp_path, xs, xs @ W_TRUE.T, xs)

    def final(seed):
        net = load_body(tmp_path, model(f'alpha="0.2" memory_max="4" seed="{seed}"'))
        try:
            net.run(ticks=30)
            return net.output("A.MATRIX")
        finally:
            net.close()
    a, b, c = final(9), final(9), final(10)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    np.testing.assert_allclose(a, W_TRUE, atol=0.3)      # well on the way after 30 ticks
