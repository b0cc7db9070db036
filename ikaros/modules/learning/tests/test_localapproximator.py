"""Tests of the LocalApproximator module."""
import numpy as np

from ikaros.testing import load_body


def approximate(tmp_path, inputs, outputs, point, attrs="", distances=None):
    body = (f'<module class="Constant" name="X" data="{inputs}"/>'
            f'<module class="Constant" name="Y" data="{outputs}"/>'
            f'<module class="Constant" name="Q" data="{point}"/>'
            f'<module class="LocalApproximator" name="L" {attrs}/>'
            '<connection source="X.OUTPUT" target="L.INPUT_TABLE" delay="0"/>'
            '<connection source="Y.OUTPUT" target="L.OUTPUT_TABLE" delay="0"/>'
            '<connection source="Q.OUTPUT" target="L.INPUT" delay="0"/>')
    if distances is not None:
        body += (f'<module class="Constant" name="D" data="{distances}"/>'
                 '<connection source="D.OUTPUT" target="L.DISTANCE_TABLE" delay="0"/>')
    net = load_body(tmp_path, body)
    try:
        net.run(ticks=2)
        return net.output("L.OUTPUT")
    finally:
        net.close()


def text(a):
    return "; ".join(" ".join(f"{v:.7g}" for v in np.atleast_1d(row)) for row in a)


def test_linear_approximation_recovers_an_affine_map(tmp_path):
    rng = np.random.default_rng(2)
    a = np.array([[1.0, -2.0], [0.5, 3.0], [0.0, 1.0]])
    b = np.array([0.3, -1.0, 2.0])
    x = rng.random((6, 2))
    y = x @ a.T + b
    point = np.array([0.4, 0.7])
    out = approximate(tmp_path, text(x), text(y), text(point))
    assert out.shape == (3,)
    np.testing.assert_allclose(out, a @ point + b, rtol=1e-4, atol=1e-4)


def test_linear_approximation_matches_least_squares_on_noisy_data(tmp_path):
    rng = np.random.default_rng(4)
    x = rng.random((8, 1))
    y = np.sin(3 * x)
    point = np.array([0.5])
    out = approximate(tmp_path, text(x), text(y), text(point))
    design = np.hstack([x, np.ones((8, 1))])
    coef = np.linalg.lstsq(design, y, rcond=None)[0]
    np.testing.assert_allclose(out, [coef[0, 0] * 0.5 + coef[1, 0]], rtol=1e-4)


def test_degenerate_inputs_give_the_mean(tmp_path):
    out = approximate(tmp_path, "1 1; 1 1; 1 1", "1; 2; 6", "1.5 0.5")
    np.testing.assert_allclose(out, [3.0], rtol=1e-5)


def test_average_and_distance_weighted_average(tmp_path):
    x, y = "0; 1; 3", "2 0; 4 1; 8 1"
    np.testing.assert_allclose(approximate(tmp_path, x, y, "2", 'type="average"'),
                               [14 / 3, 2 / 3], rtol=1e-6)
    w = 1 / np.array([2.0, 1.0, 1.0])
    expected = w @ np.array([[2, 0], [4, 1], [8, 1]]) / w.sum()
    np.testing.assert_allclose(approximate(tmp_path, x, y, "2",
                                           'type="distance_weighted_average"'),
                               expected, rtol=1e-6)
    # an example at distance 0 gives its output
    np.testing.assert_allclose(approximate(tmp_path, x, y, "1",
                                           'type="distance_weighted_average"'), [4, 1])


def test_missing_neighbours_are_left_out(tmp_path):
    # KNN marks missing rows with distance -1 (and zero inputs and outputs)
    out = approximate(tmp_path, "0; 2; 0", "1; 5; 0", "1", 'type="average"',
                      distances="1 1 -1")
    np.testing.assert_allclose(out, [3.0])
    out = approximate(tmp_path, "0; 2; 0", "1; 5; 0", "1", distances="1 1 -1")
    np.testing.assert_allclose(out, [3.0], rtol=1e-6)
    out = approximate(tmp_path, "0; 2; 0", "1; 5; 0", "1", distances="-1 -1 -1")
    np.testing.assert_array_equal(out, [0])
