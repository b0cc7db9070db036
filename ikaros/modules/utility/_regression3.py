"""The Ikaros 3 outputs of RegressionStatistics (today's interface: SCATTER_X, SCATTER_Y,
SAMPLE_COUNT, LINEAR_REGRESSION, MODEL_COMPARISON), computed as this project reads their
names: the reference gives the interface and not the computation."""
import math

import numpy as np

# LINEAR_REGRESSION's rows, as the six results of an ordinary least-squares line
LINEAR_ROWS = ("slope", "intercept", "r", "p", "slope_stderr", "intercept_stderr")
# MODEL_COMPARISON's rows (the models) and columns (R², AIC)
COMPARED = ("constant", "linear", "quadratic", "cubic", "logarithmic", "exponential",
            "power")


def linear_regression(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """slope, intercept, Pearson's r, the two-sided p-value of the slope (Student's t with n
    - 2 degrees of freedom), and the standard errors of the slope and of the intercept.
    All NaN with fewer than 2 pairs or one x value; p and the standard errors NaN with 2."""
    out = np.full(6, np.nan)
    n = len(x)
    if n < 2:
        return out
    mx, my = x.mean(), y.mean()
    sxx, syy, sxy = np.sum((x - mx) ** 2), np.sum((y - my) ** 2), np.sum((x - mx) * (y - my))
    if sxx <= 0:
        return out
    slope = sxy / sxx
    out[0], out[1] = slope, my - slope * mx
    out[2] = sxy / math.sqrt(sxx * syy) if syy > 0 else 0.0
    if n > 2:
        df = n - 2
        residual = max(0.0, syy - slope * sxy) / df
        out[4] = math.sqrt(residual / sxx)
        out[5] = out[4] * math.sqrt(np.sum(x * x) / n)
        if out[4] > 0:
            t = slope / out[4]
            out[3] = regularized_beta(df / 2, 0.5, df / (df + t * t))
        else:
            out[3] = 0.0
    return out


def regularized_beta(a: float, b: float, x: float) -> float:
    """I_x(a, b), the regularized incomplete beta function, by its continued fraction
    (modified Lentz), using the symmetry I_x(a, b) = 1 - I_(1-x)(b, a) where that converges
    faster."""
    if x <= 0:
        return 0.0
    if x >= 1:
        return 1.0
    if x > (a + 1) / (a + b + 2):
        return 1.0 - regularized_beta(b, a, 1.0 - x)
    front = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) +
                     a * math.log(x) + b * math.log1p(-x)) / a
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    result = d
    for m in range(1, 300):
        for numerator in (m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m)),
                          -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))):
            d = 1.0 + numerator * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + numerator / c
            c = c if abs(c) > tiny else tiny
            result *= c * d
        if abs(c * d - 1.0) < 1e-15:
            break
    return front * result


def _design(model: str, x: np.ndarray):
    """The columns of the least-squares problem of a model (after its log transform of x),
    or None when x is outside the model's domain."""
    if model in ("logarithmic", "power"):
        if np.any(x <= 0):
            return None
        x = np.log(x)
    degree = {"constant": 0, "quadratic": 2, "cubic": 3}.get(model, 1)
    scale = np.max(np.abs(x)) or 1.0            # scaled, so small or large units fit well
    return np.vander(x / scale, degree + 1)


def model_comparison(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """For each model of COMPARED fitted by least squares to the pairs: R² (1 - SSres /
    SStot, of y itself; exponential and power are fitted to ln y) and AIC (n ln(SSres / n)
    + 2 p for p coefficients). NaN where the model cannot be fitted: fewer pairs than its
    coefficients plus one, fewer distinct x values than its coefficients, or data outside
    its domain."""
    out = np.full((len(COMPARED), 2), np.nan)
    n = len(x)
    if n < 2:
        return out
    ss_tot = float(np.sum((y - y.mean()) ** 2))
    for row, model in enumerate(COMPARED):
        design = _design(model, x)
        if design is None or n <= design.shape[1] or len(np.unique(x)) < design.shape[1] \
                or (model in ("exponential", "power") and np.any(y <= 0)):
            continue
        target = np.log(y) if model in ("exponential", "power") else y
        coef = np.linalg.lstsq(design, target, rcond=None)[0]
        fitted = design @ coef
        if model in ("exponential", "power"):
            fitted = np.exp(fitted)
        ss_res = float(np.sum((y - fitted) ** 2))
        out[row, 0] = 1.0 - ss_res / ss_tot if ss_tot > 0 else 1.0
        out[row, 1] = n * math.log(ss_res / n) + 2 * design.shape[1] if ss_res > 0 \
            else -math.inf
    return out


class SeriesWindows:
    """The latest ``capacity`` finite pairs (x, y) of each of ``series`` data series."""

    def __init__(self, capacity: int, series: int):
        self.x = np.zeros((series, capacity))
        self.y = np.zeros((series, capacity))
        self.count = np.zeros(series, dtype=np.int64)
        self.next = np.zeros(series, dtype=np.int64)

    def add(self, x: np.ndarray, y: np.ndarray) -> None:
        """One pair per series (the ones with a value that is not finite are skipped)."""
        capacity = self.x.shape[1]
        for j in np.flatnonzero(np.isfinite(x) & np.isfinite(y)):
            self.x[j, self.next[j]], self.y[j, self.next[j]] = x[j], y[j]
            self.next[j] = (self.next[j] + 1) % capacity
            self.count[j] = min(capacity, self.count[j] + 1)

    def pairs(self, j: int) -> tuple[np.ndarray, np.ndarray]:
        """Series j's pairs, oldest first."""
        n, capacity = self.count[j], self.x.shape[1]
        order = (self.next[j] - n + np.arange(n)) % capacity
        return self.x[j, order], self.y[j, order]

    def clear(self) -> None:
        self.count[:] = 0
        self.next[:] = 0
