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
                         r"value \(shared by every sample\) or have as many elements as "
                         r"SAMPLE"),
    ("1 2 3", "1 2; 3 4", "", r"X has the shape \(3,\) and SAMPLE the shape \(2, 2\)"),
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


# --- Ikaros 3's interface (IKAROS3-INTERFACES: X, Y, SAMPLE; SCATTER_X/Y, SAMPLE_COUNT,
# LINEAR_REGRESSION, MODEL_COMPARISON; max_samples, labels), read as the description says
def _t_p_value(t, df):
    """Two-sided p of Student's t, by integrating its density numerically."""
    grid = np.linspace(abs(t), abs(t) + 200, 400001)
    density = (1 + grid ** 2 / df) ** (-(df + 1) / 2)
    whole = np.linspace(0, 200, 400001)
    return np.trapezoid(density, grid) / np.trapezoid((1 + whole ** 2 / df) **
                                                      (-(df + 1) / 2), whole)


def _line(x, y):
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    n = len(x)
    slope, intercept = np.polyfit(x, y, 1)
    r = np.corrcoef(x, y)[0, 1]
    residual = y - (intercept + slope * x)
    s2 = residual @ residual / (n - 2)
    se = np.sqrt(s2 / np.sum((x - x.mean()) ** 2))
    return [slope, intercept, r, _t_p_value(slope / se, n - 2), se,
            se * np.sqrt(np.mean(x * x))]


def _v3_model(tmp_path, attrs="", sample=False):
    body = ('<module class="Constant" name="X" data="0"/>'
            '<module class="Constant" name="Y" data="0, 0"/>'
            f'<module class="RegressionStatistics" name="R" {attrs}/>'
            '<connection source="X.OUTPUT" target="R.X" delay="0"/>'
            '<connection source="Y.OUTPUT" target="R.Y" delay="0"/>')
    if sample:
        body += ('<module class="Constant" name="S" data="1"/>'
                 '<connection source="S.OUTPUT" target="R.SAMPLE" delay="0"/>')
    return load(tmp_path, body, dialect="3")


XS = [1.0, 2.0, 3.0, 4.5, 5.0, 7.0]
YS = [[2.0, 9.0], [4.5, 7.5], [5.5, 7.0], [9.0, 4.0], [10.5, 3.5], [13.0, 1.0]]


def test_ikaros_3_scatter_count_and_linear_regression_per_series(tmp_path):
    net = _v3_model(tmp_path, 'max_samples="8" labels="left, right"')
    with net:
        assert net.output("R.MODEL_COMPARISON").shape == (7, 2)
        for x, y in zip(XS, YS):
            net.set_parameter("X.data", str(x))
            net.set_parameter("Y.data", f"{y[0]}, {y[1]}")
            net.step()
        assert net.parameter("R.labels") == "left, right"
        assert net.output("R.SAMPLE_COUNT").tolist() == [6, 6]
        scatter_x, scatter_y = net.output("R.SCATTER_X"), net.output("R.SCATTER_Y")
        assert scatter_x.shape == (8, 2)
        assert np.array_equal(scatter_x[:6], np.array([XS, XS], np.float32).T)
        assert np.array_equal(scatter_y[:6], np.array(YS, np.float32))
        assert not scatter_x[6:].any() and not scatter_y[6:].any()
        got = net.output("R.LINEAR_REGRESSION")
        assert got.shape == (6, 2)
        for j in range(2):
            want = _line(XS, [row[j] for row in YS])
            assert np.allclose(got[:, j], want, rtol=1e-4, atol=1e-6), j


def test_ikaros_3_model_comparison_pools_the_series(tmp_path):
    net = _v3_model(tmp_path)
    with net:
        for x, y in zip(XS, YS):
            net.set_parameter("X.data", str(x))
            net.set_parameter("Y.data", f"{y[0]}, {y[1]}")
            net.step()
        x = np.array(XS * 2)
        y = np.array([row[0] for row in YS] + [row[1] for row in YS])
        n, ss_tot = len(x), np.sum((y - y.mean()) ** 2)
        want = []
        for degree in (0, 1, 2, 3):                    # constant ... cubic
            fitted = np.polyval(np.polyfit(x, y, degree), x)
            want.append((fitted, degree + 1))
        fitted = np.polyval(np.polyfit(np.log(x), y, 1), np.log(x))      # logarithmic
        want.append((fitted, 2))
        b, log_a = np.polyfit(x, np.log(y), 1)                          # exponential
        want.append((np.exp(log_a + b * x), 2))
        b, log_a = np.polyfit(np.log(x), np.log(y), 1)                  # power
        want.append((np.exp(log_a) * x ** b, 2))
        got = net.output("R.MODEL_COMPARISON")
        for row, (fitted, p) in enumerate(want):
            ss_res = np.sum((y - fitted) ** 2)
            assert got[row, 0] == pytest.approx(1 - ss_res / ss_tot, abs=1e-5), row
            assert got[row, 1] == pytest.approx(n * np.log(ss_res / n) + 2 * p, rel=1e-5), row


def test_ikaros_3_sample_says_when_and_max_samples_keeps_the_latest(tmp_path):
    net = _v3_model(tmp_path, 'max_samples="3"', sample=True)
    with net:
        kept = []
        for k, (x, y) in enumerate(zip(XS, YS)):
            on = k % 2 == 0
            net.set_parameter("S.data", "1" if on else "0")
            net.set_parameter("X.data", str(x))
            net.set_parameter("Y.data", f"{y[0]}, {y[1]}")
            net.step()
            if on:
                kept.append((x, y[0]))
        kept = kept[-3:]
        assert net.output("R.SAMPLE_COUNT").tolist() == [3, 3]
        assert np.allclose(net.output("R.SCATTER_X")[:, 0], [k[0] for k in kept])
        assert np.allclose(net.output("R.SCATTER_Y")[:, 0], [k[1] for k in kept])
        net.command("R", "reset")
        assert net.output("R.SAMPLE_COUNT").tolist() == [0, 0]
        assert np.isnan(net.output("R.LINEAR_REGRESSION")).all()


def test_two_pairs_give_a_line_without_p_and_errors(tmp_path):
    net = _v3_model(tmp_path)
    with net:
        for x, y in ((1, "1, 5"), (3, "2, 1")):
            net.set_parameter("X.data", str(x))
            net.set_parameter("Y.data", y)
            net.step()
        got = net.output("R.LINEAR_REGRESSION")
        assert np.allclose(got[:3, 0], [0.5, 0.5, 1]) and np.allclose(got[:3, 1], [-2, 7, -1])
        assert np.isnan(got[3:]).all()
