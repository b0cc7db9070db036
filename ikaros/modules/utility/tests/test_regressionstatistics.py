"""Tests of RegressionStatistics against independent fits (numpy.polyfit) of the same pairs."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load, matrix_text

ALL = ["linear", "quadratic", "logarithmic", "exponential", "power"]


def regression(tmp_path, x, y, attrs="", collect=None):
    body = (f'<module class="Constant" name="X" data="{matrix_text(x)}"/>'
            f'<module class="Constant" name="Y" data="{matrix_text(y)}"/>'
            f'<module class="RegressionStatistics" name="R" {attrs}/>'
            '<connection source="X.OUTPUT" target="R.X" delay="0"/>'
            '<connection source="Y.OUTPUT" target="R.SAMPLE" delay="0"/>')
    if collect is not None:
        body += (f'<module class="Constant" name="G" data="{collect}"/>'
                 '<connection source="G.OUTPUT" target="R.COLLECT" delay="0"/>')
    return load(tmp_path, body)


def reference(model, x, y):
    """(a, b, c), R² and RMSE of the model by numpy.polyfit, in double precision."""
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    if model in ("linear", "quadratic"):
        c = np.polyfit(x, y, 1 if model == "linear" else 2)[::-1]
        coef = np.append(c, [0] * (3 - len(c)))
        fitted = np.polyval(c[::-1], x)
    elif model == "logarithmic":
        b, a = np.polyfit(np.log(x), y, 1)
        coef, fitted = np.array([a, b, 0]), a + b * np.log(x)
    elif model == "exponential":
        b, log_a = np.polyfit(x, np.log(y), 1)
        coef, fitted = np.array([np.exp(log_a), b, 0]), np.exp(log_a) * np.exp(b * x)
    else:
        b, log_a = np.polyfit(np.log(x), np.log(y), 1)
        coef, fitted = np.array([np.exp(log_a), b, 0]), np.exp(log_a) * x ** b
    ss_res = np.sum((y - fitted) ** 2)
    r2 = 1 - ss_res / np.sum((y - y.mean()) ** 2)
    return coef, r2, np.sqrt(ss_res / len(y))


def adjusted(r2, n, p):
    return 1 - (1 - r2) * (n - 1) / (n - p)


def check_against_reference(net, x, y, models=ALL):
    coefficients, r2, rmse = (net.output(f"R.{k}") for k in ("COEFFICIENTS", "R2", "RMSE"))
    scores = []
    for row, model in enumerate(models):
        coef, want_r2, want_rmse = reference(model, x, y)
        assert np.allclose(coefficients[row], coef, rtol=1e-5, atol=0), model
        assert r2[row] == pytest.approx(want_r2, abs=1e-6), model
        # an exact fit leaves residuals of rounding size: compared on the data's scale
        assert rmse[row] == pytest.approx(want_rmse, rel=1e-5,
                                          abs=1e-12 * float(np.abs(y).max())), model
        scores.append(adjusted(want_r2, len(x), 3 if model == "quadratic" else 2))
    assert net.output("R.BEST")[0] == int(np.argmax(scores))


def test_every_model_matches_polyfit_and_the_best_is_chosen(tmp_path):
    x = np.array([1, 2, 3, 4, 5, 6, 7, 8], np.float32)
    y = np.array([2.1, 3.9, 6.2, 7.8, 10.1, 12.2, 13.8, 16.1], np.float32)
    net = regression(tmp_path, x, y, 'capacity="8"')
    try:
        assert net.output("R.BEST").tolist() == [-1]       # nothing collected yet
        assert np.isnan(net.output("R.R2")).all()
        net.step()
        check_against_reference(net, x, y)
        assert net.output("R.BEST").tolist() == [0]         # linear
        a, b, _ = reference("linear", x, y)[0]
        assert np.allclose(net.output("R.PREDICTION"), a + b * x, rtol=1e-6)
        assert net.output("R.COUNT").tolist() == [8] and net.output("R.MASKED").tolist() == [0]
    finally:
        net.close()


@pytest.mark.parametrize("scale", [1e-9, 1e-3, 1e6])
def test_small_and_large_scales_fit_as_well(tmp_path, scale):
    """The model comparison does not depend on the units: quadratic data scaled by 1e-9
    fits exactly, the other models do not, and the same model is best."""
    t = np.arange(1, 11, dtype=np.float64)
    x = (t * scale).astype(np.float32)
    y = ((0.5 + 0.25 * t - 0.125 * t * t) * scale).astype(np.float32)
    net = regression(tmp_path, x, y, 'capacity="10" models="linear, quadratic"')
    try:
        net.step()
        check_against_reference(net, x, y, ["linear", "quadratic"])
        assert net.output("R.BEST").tolist() == [1]
        assert net.output("R.R2")[1] == pytest.approx(1, abs=1e-6)
        assert net.output("R.R2")[0] < 0.95
    finally:
        net.close()


def test_growth_curves_pick_their_own_model(tmp_path):
    x = np.array([1, 2, 3, 4, 5, 6], np.float32)
    for models, y, best in (("linear, exponential, power", 3 * np.exp(0.5 * x), 1),
                            ("linear, exponential, power", 2 * x ** 1.5, 2),
                            ("linear, logarithmic", 1 + 2 * np.log(x), 1)):
        net = regression(tmp_path, x, y.astype(np.float32), f'capacity="6" models="{models}"')
        try:
            net.step()
            names = [m.strip() for m in models.split(",")]
            check_against_reference(net, x, y.astype(np.float32), names)
            assert net.output("R.BEST").tolist() == [best]
        finally:
            net.close()


def test_a_window_keeps_the_latest_pairs(tmp_path):
    net = regression(tmp_path, [0, 0], [0, 0], 'capacity="5" models="linear, quadratic"')
    try:
        xs, ys = [], []
        for k in range(6):
            x, y = [k, k + 0.5], [k * k, 3 - k]
            net.set_parameter("X.data", matrix_text(x))
            net.set_parameter("Y.data", matrix_text(y))
            net.step()
            xs += x
            ys += y
            assert net.output("R.COUNT").tolist() == [min(5, len(xs))]
        check_against_reference(net, xs[-5:], ys[-5:], ["linear", "quadratic"])
    finally:
        net.close()


def test_non_finite_pairs_are_counted_and_not_used(tmp_path):
    x = np.array([1, 2, np.nan, 3, 4, 5, np.inf], np.float32)
    y = np.array([3, 5, 1, np.inf, 9, -np.nan, 2], np.float32)
    net = regression(tmp_path, x, y, 'models="linear, quadratic"')
    try:
        net.step()
        assert net.output("R.MASKED").tolist() == [4]
        assert net.output("R.COUNT").tolist() == [3]
        check_against_reference(net, [1, 2, 4], [3, 5, 9], ["linear"])
        assert np.isnan(net.output("R.COEFFICIENTS")[1]).all()   # 3 pairs: no quadratic
        net.step()
        assert net.output("R.MASKED").tolist() == [8]
        net.command("R", "reset")
        assert net.output("R.MASKED").tolist() == [0] and net.output("R.COUNT").tolist() == [0]
        assert net.output("R.BEST").tolist() == [-1]
    finally:
        net.close()


def test_models_outside_their_domain_or_without_enough_pairs_are_nan(tmp_path):
    x = np.array([-1, 0, 1, 2], np.float32)
    y = np.array([1, 2, 3, 4], np.float32)
    net = regression(tmp_path, x, y, 'capacity="4"')
    try:
        net.step()
        r2 = net.output("R.R2")
        assert r2[:2].tolist() == [1, 1] and r2[3] < 1          # exponential: y > 0
        assert np.isnan(r2[2]) and np.isnan(r2[4])              # logarithmic, power: x <= 0
        assert net.output("R.BEST").tolist() == [0]             # linear wins its tie
        assert np.isnan(net.output("R.RMSE")[[2, 4]]).all()
    finally:
        net.close()


def test_one_x_shared_by_several_samples(tmp_path):
    net = regression(tmp_path, [2], [1, 2, 3], 'models="linear"')
    try:
        net.step()
        assert net.output("R.COUNT").tolist() == [3]
        assert net.output("R.BEST").tolist() == [-1]           # one distinct x: no line
        net.set_parameter("X.data", "4")
        net.set_parameter("Y.data", "5 6 7")
        net.step()
        check_against_reference(net, [2, 2, 2, 4, 4, 4], [1, 2, 3, 5, 6, 7], ["linear"])
        assert net.output("R.PREDICTION").tolist() == pytest.approx([6, 6, 6])
    finally:
        net.close()


def test_collect_gates_the_pairs_and_the_prediction_follows_x(tmp_path):
    net = regression(tmp_path, [1, 2, 3], [3, 5, 7], 'models="linear"', collect="0")
    try:
        net.step()
        assert net.output("R.COUNT").tolist() == [0]
        net.set_parameter("G.data", "1")
        net.step()
        assert net.output("R.COUNT").tolist() == [3]
        assert net.output("R.PREDICTION").tolist() == pytest.approx([3, 5, 7])
        net.set_parameter("G.data", "0")
        net.set_parameter("X.data", "10 20 -1")      # not collected, but predicted
        net.step()
        assert net.output("R.COUNT").tolist() == [3]
        assert net.output("R.PREDICTION").tolist() == pytest.approx([21, 41, -1])
        assert net.output("R.COEFFICIENTS")[0].tolist() == pytest.approx([1, 2, 0])
    finally:
        net.close()


def test_capacity_is_fixed_while_running(tmp_path):
    net = regression(tmp_path, [1, 2], [1, 2], 'capacity="3"')
    try:
        with pytest.raises(ValueError, match='parameter "R.capacity" is fixed while the '
                                             'model runs'):
            net.set_parameter("R.capacity", 10)
        for _ in range(3):
            net.step()
        assert net.parameter("R.capacity") == 3 and net.output("R.COUNT").tolist() == [3]
    finally:
        net.close()


@pytest.mark.parametrize("x, y, attrs, message", [
    ("1 2", "1 2 3", "", r"X has the shape \(2,\) and SAMPLE the shape \(3,\): X must be one "
                         r"value \(shared by every sample\) or have the shape of SAMPLE"),
    ("1 2 3 4", "1 2; 3 4", "", r"X has the shape \(4,\) and SAMPLE the shape \(2, 2\)"),
    ("1", "1", 'models="linear, cubic"', r'models="linear, cubic": cubic is not among '
                                         r'linear, quadratic'),
    ("1", "1", 'capacity="0"', "capacity"),
])
def test_bad_shapes_and_parameters_are_build_errors(tmp_path, x, y, attrs, message):
    with pytest.raises(ModelError, match=message) as e:
        load(tmp_path, f'<module class="Constant" name="X" data="{x}"/>'
                       f'<module class="Constant" name="Y" data="{y}"/>'
                       f'<module class="RegressionStatistics" name="R" {attrs}/>'
                       '<connection source="X.OUTPUT" target="R.X"/>'
                       '<connection source="Y.OUTPUT" target="R.SAMPLE"/>')
    assert "model.ikg:" in str(e.value)
