"""RegressionStatistics: fits regression models to the latest (X, SAMPLE) pairs and
compares them."""
import math

import numpy as np
from numpy.polynomial import Polynomial

from ikaros.module import Input, Module, Output, Parameter

from ._regression3 import COMPARED, SeriesWindows, linear_regression, model_comparison

# name: (number of coefficients, whether x must be > 0, whether y must be > 0)
MODELS = {"linear": (2, False, False), "quadratic": (3, False, False),
          "logarithmic": (2, True, False), "exponential": (2, False, True),
          "power": (2, True, True)}
TIE = 1e-9      # a model listed later must beat the best adjusted R² by more than this


def fit(model: str, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The coefficients (a, b, c) of ``model`` fitted to the pairs by least squares:
    y = a + b x + c x² (linear: c = 0), y = a + b ln x, y = a e^(b x) and y = a x^b (the
    last two fitted as straight lines to ln y). The caller checks the domain and that
    there are enough distinct values."""
    degree = 2 if model == "quadratic" else 1
    u = np.log(x) if model in ("logarithmic", "power") else x
    v = np.log(y) if model in ("exponential", "power") else y
    coef = np.zeros(3)
    found = Polynomial.fit(u, v, degree).convert().coef   # fitted on a scaled x: stable
    coef[:len(found)] = found
    if model in ("exponential", "power"):
        coef[0] = math.exp(coef[0])
    return coef


def predict(model: str, coef: np.ndarray, x: np.ndarray) -> np.ndarray:
    a, b, c = coef
    if model == "logarithmic":
        return a + b * np.log(x)
    if model == "exponential":
        return a * np.exp(b * x)
    if model == "power":
        return a * np.power(x, b)
    return a + b * x + c * x * x


class RegressionStatistics(Module):
    """Fits regression models to the latest ``capacity`` pairs of an explanatory value and
    a sample, and says which model describes them best. Each tick adds the pairs (X[i],
    SAMPLE[i]) element by element (X has the shape of SAMPLE, or is one value shared by
    every sample: one stimulus, several responses); with COLLECT
    connected, only on ticks when it is above 0. A pair with a value that is nan or
    infinite is not used: it is counted in MASKED. When the window is full the oldest pair
    makes room. ``models`` lists the models fitted, one row of COEFFICIENTS, R2 and RMSE
    each, in the order given: linear y = a + b x, quadratic y = a + b x + c x²,
    logarithmic y = a + b ln x, exponential y = a e^(b x) and power y = a x^b (the last
    two by least squares on ln y, as spreadsheet trendlines). A row of COEFFICIENTS holds
    a, b, c (0 where a model has none). A model is fitted when the window holds more pairs
    than it has coefficients, with at least as many distinct x values as coefficients, and
    every pair is in its domain (x > 0 for logarithmic and power, y > 0 for exponential and
    power); otherwise its row is nan. R2 is 1 - SSres/SStot on the samples themselves (1
    when all samples are equal) and RMSE the root mean square of the residuals. BEST is
    the index of the fitted model with the highest adjusted R² (1 - (1 - R²)(n - 1)/(n -
    p) for n pairs and p coefficients), the one listed first on a tie (within 1e-9); -1
    when none is fitted. PREDICTION is the best model's value at this tick's X for each
    sample. X and SAMPLE of shapes that do not fit is a build error naming both shapes;
    ``capacity`` is fixed while the model runs. The command ``reset`` empties the window
    and MASKED. The fits use NumPy in double precision on a scaled x, so data of a small
    or large scale (1e-9, 1e6) fit as well; they are made on ticks that add pairs, at
    about 0.15 ms per model for a window of 100 to 1000 pairs.

    Ikaros 3's interface (today's) is accepted too; the reference gives its names, not its
    computation, so what follows is this project's reading of them. Y is Ikaros 3's name
    for the observed values: when Y is connected it is the data (one series per element,
    X one value for all or one per series) and SAMPLE, optional, says when to add pairs
    (on ticks when any element is above 0; every tick when unconnected); COLLECT still
    works. Each series keeps its latest ``max_samples`` finite pairs: SCATTER_X and
    SCATTER_Y hold them, one column per series, oldest first (rows after SAMPLE_COUNT's
    count are 0). LINEAR_REGRESSION has one column per series with the six results of a
    least-squares line: slope, intercept, Pearson's r, the two-sided p-value of the slope
    (Student's t, n - 2 degrees of freedom), and the standard errors of the slope and the
    intercept (NaN where they do not exist). MODEL_COMPARISON fits every series' pairs
    together with the models constant, linear, quadratic, cubic, logarithmic,
    exponential and power (its rows) and gives R² and AIC (n ln(SSres / n) + 2 p; its
    columns), NaN where a model cannot be fitted. ``labels`` names the series (comma
    separated) for the web UI. The command ``reset`` empties these windows too. Without
    Y, SAMPLE is the data (this project's interface) and the Ikaros 3 outputs are computed
    from it in the same way."""

    capacity = Parameter(100, "the number of latest pairs the models are fitted to",
                         type="int", range=(1, None), fixed=True)
    models = Parameter("linear, quadratic, logarithmic, exponential, power",
                       "the models to fit, in the order of the rows of the outputs "
                       "(comma-separated: linear, quadratic, logarithmic, exponential, "
                       "power)", fixed=True)
    max_samples = Parameter(1024, "Ikaros 3: the number of latest pairs of each series kept "
                            "for SCATTER_X, SCATTER_Y, LINEAR_REGRESSION and "
                            "MODEL_COMPARISON", type="int", range=(1, None), fixed=True)
    labels = Parameter("", "Ikaros 3: the names of the series, comma separated (for the "
                       "web UI)")
    X = Input("the explanatory values: one for every sample, or one value shared by all",
              flatten=True)
    Y = Input("Ikaros 3: the observed values, one series per element; when connected, "
              "SAMPLE says when to add pairs", flatten=True, optional=True)
    SAMPLE = Input("the observed values (without Y), one pair with X per element; with Y "
                   "(Ikaros 3): pairs are added on ticks when any element is above 0",
                   optional=True)
    COLLECT = Input("pairs are added on ticks when any element is above 0 (every tick "
                    "when unconnected)", optional=True)
    COEFFICIENTS = Output("a, b, c of each model: one row per model")
    R2 = Output("the coefficient of determination of each model (nan: not fitted)")
    RMSE = Output("the root mean square error of each model (nan: not fitted)")
    BEST = Output("the row of the best model (highest adjusted R²); -1 when none is "
                  "fitted", size="1")
    PREDICTION = Output("the best model's value at X for each sample (nan when none is "
                        "fitted); the shape of SAMPLE")
    COUNT = Output("the number of pairs in the window", size="1")
    MASKED = Output("the number of pairs not used because a value was nan or infinite",
                    size="1")
    SCATTER_X = Output("Ikaros 3: the x of each series' latest pairs, one column per series")
    SCATTER_Y = Output("Ikaros 3: the y of each series' latest pairs, one column per series")
    SAMPLE_COUNT = Output("Ikaros 3: the number of pairs kept for each series")
    LINEAR_REGRESSION = Output("Ikaros 3: slope, intercept, r, p, the slope's and the "
                               "intercept's standard errors; one column per series")
    MODEL_COMPARISON = Output("Ikaros 3: R² and AIC of the models constant, linear, "
                              "quadratic, cubic, logarithmic, exponential and power, fitted "
                              "to all series together", shape=f"{len(COMPARED)}, 2")

    def configure(self):
        names = [m.strip().lower() for m in self.models.split(",") if m.strip()]
        unknown = [m for m in names if m not in MODELS]
        if unknown or not names:
            raise ValueError(f'models="{self.models}": {", ".join(unknown) or "none given"}'
                             f' {"is" if len(unknown) == 1 else "are"} not among '
                             f'{", ".join(MODELS)}')
        self._models = names
        self.set_output_shape("COEFFICIENTS", (len(names), 3))
        self.set_output_shape("R2", (len(names),))
        self.set_output_shape("RMSE", (len(names),))

    def _data_name(self) -> str:
        return "Y" if self.connected("Y") else "SAMPLE"

    def set_sizes(self):
        if not self.connected("Y") and not self.connected("SAMPLE"):
            raise ValueError("connect the observed values to Y (Ikaros 3) or SAMPLE")
        name = self._data_name()
        x, sample = self.input_shape("X"), self.input_shape(name)
        if x is None or sample is None:
            return
        if math.prod(x) != math.prod(sample) and math.prod(x) != 1:
            raise ValueError(f"X has the shape {x} and {name} the shape {sample}: X must be "
                             f"one value (shared by every sample) or have as many elements "
                             f"as {name}")
        n = math.prod(sample)
        self.set_output_shape("PREDICTION", sample)
        self.set_output_shape("SCATTER_X", (self.max_samples, n))
        self.set_output_shape("SCATTER_Y", (self.max_samples, n))
        self.set_output_shape("SAMPLE_COUNT", (n,))
        self.set_output_shape("LINEAR_REGRESSION", (6, n))

    def init(self):
        self._x = np.zeros(self.capacity)           # the window: a ring of pairs
        self._y = np.zeros(self.capacity)
        self._data = self.Y if self.Y is not None else self.SAMPLE
        self._triggers = [t for t in (self.COLLECT, self.Y is not None and self.SAMPLE)
                          if t is not None and t is not False]
        self._series = SeriesWindows(self.max_samples, self._data.size)
        self._reset()

    def _reset(self):
        self._count = 0
        self._next = 0
        self._masked = 0
        self.MASKED[0] = 0
        self._series.clear()
        self._fit_window()
        self._fit_series()
        self._predict()

    def tick(self):
        if all(t.size and t.max() > 0 for t in self._triggers):
            y = self._data.reshape(-1).astype(np.float64)
            x = np.broadcast_to(self.X.reshape(-1).astype(np.float64), y.shape)
            if self._add(x, y):
                self._fit_window()
            self._series.add(x, y)
            self._fit_series()
        self._predict()

    def _fit_series(self):
        """The Ikaros 3 outputs, from each series' window."""
        series = self._series
        self.SCATTER_X.fill(0)
        self.SCATTER_Y.fill(0)
        for j in range(len(series.count)):
            x, y = series.pairs(j)
            self.SCATTER_X[:len(x), j] = x
            self.SCATTER_Y[:len(y), j] = y
            self.LINEAR_REGRESSION[:, j] = linear_regression(x, y)
        self.SAMPLE_COUNT[...] = series.count
        pooled = [series.pairs(j) for j in range(len(series.count))]
        self.MODEL_COMPARISON[...] = model_comparison(
            np.concatenate([p[0] for p in pooled]), np.concatenate([p[1] for p in pooled]))

    def _add(self, x: np.ndarray, y: np.ndarray) -> int:
        """Add the finite pairs to the window; returns how many were added."""
        finite = np.isfinite(x) & np.isfinite(y)
        added = int(np.count_nonzero(finite))
        self._masked += finite.size - added
        self.MASKED[0] = self._masked
        x, y = x[finite][-self.capacity:], y[finite][-self.capacity:]
        at = (self._next + np.arange(len(x))) % self.capacity
        self._x[at], self._y[at] = x, y
        self._next = (self._next + len(x)) % self.capacity
        self._count = min(self.capacity, self._count + len(x))
        return added

    def _fit_window(self):
        """Fit every model to the window and choose the best."""
        n = self._count
        x, y = self._x[:n], self._y[:n]        # the order of the pairs does not matter
        coefficients, r2, rmse = self.COEFFICIENTS, self.R2, self.RMSE
        best, best_score, self._best = -1, -math.inf, None
        for row, model in enumerate(self._models):
            coef = self._fit(model, x, y)
            if coef is None:
                coefficients[row] = r2[row] = rmse[row] = np.nan
                continue
            residual = y - predict(model, coef, x)
            ss_res = float(residual @ residual)
            ss_tot = float(np.sum(np.square(y - y.mean())))
            fit_r2 = 1.0 - ss_res / ss_tot if ss_tot > 0 else 1.0
            coefficients[row] = coef
            r2[row] = fit_r2
            rmse[row] = math.sqrt(ss_res / n)
            p = MODELS[model][0]
            adjusted = 1.0 - (1.0 - fit_r2) * (n - 1) / (n - p)
            if adjusted > best_score + TIE:
                best, best_score, self._best = row, adjusted, (model, coef)
        self.BEST[0] = best
        self.COUNT[0] = n

    def _predict(self):
        """PREDICTION: the best model at this tick's X."""
        if self._best is None:
            self.PREDICTION.fill(np.nan)
            return
        x = self.X.reshape(-1) if self.X.size == 1 else \
            self.X.reshape(self.PREDICTION.shape)                   # one X for all samples
        with np.errstate(all="ignore"):         # X may be outside the model's domain
            self.PREDICTION[...] = predict(*self._best, x.astype(np.float64))

    @staticmethod
    def _fit(model: str, x: np.ndarray, y: np.ndarray) -> np.ndarray | None:
        """The model's coefficients, or None when it cannot be fitted to the pairs."""
        p, positive_x, positive_y = MODELS[model]
        if len(x) <= p or (positive_x and np.any(x <= 0)) or (positive_y and np.any(y <= 0)):
            return None
        if len(np.unique(x)) < p:
            return None
        return fit(model, x, y)

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._reset()
