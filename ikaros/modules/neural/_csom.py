"""The machinery shared by the convolutional self-organising maps CSOM, CSOM_L and CSOM_PCA.

A map of som_size_y x som_size_x units (weight vectors of rf_size_y x rf_size_x elements,
shared by every position) is applied to every receptive field of the input. Receptive fields
are gathered with one precomputed index array, so a tick is a few matrix products.
"""
import math
import os

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


def resolve(module, filename):
    """A file name relative to the folder of the model file."""
    if os.path.isabs(filename):
        return filename
    model_file = getattr(module.element, "file", None)
    folder = os.path.dirname(os.path.abspath(model_file)) if model_file else os.getcwd()
    return os.path.join(folder, filename)


def field_extent(rf, block, span):
    """The input extent one receptive field covers: blocks of ``block`` elements with
    ``span`` elements between them."""
    return rf + (math.ceil(rf / block) - 1) * span


class SOMBase(Module):
    """Base of the convolutional SOMs (not a class of its own)."""

    rf_size_x = Parameter(3, "receptive field width")
    rf_size_y = Parameter(3, "receptive field height")
    rf_inc_x = Parameter(1, "horizontal step between receptive fields")
    rf_inc_y = Parameter(1, "vertical step between receptive fields")
    som_size_x = Parameter(3, "number of map units across")
    som_size_y = Parameter(3, "number of map units down")
    output_type = Parameter("combined", "layout of OUTPUT: combined (a som-sized block for each "
                            "receptive field) or separate (a map-sized block for each unit)",
                            options="combined,separate")
    topology = Parameter("plane", "topology of the map: plane, or torus (edges wrap around)",
                         options="plane,torus")
    alpha = Parameter(0.00001, "the learning rate at the start")
    alpha_min = Parameter(0.0000001, "the learning rate never decays below this")
    alpha_max = Parameter(0.1, "the learning rate is never above this")
    alpha_decay = Parameter(0.9999, "the learning rate is multiplied by this after each tick")
    sigma = Parameter(1.0, "neighbourhood radius at the start, as a multiple of the map's "
                      "half-diagonal hypot(som_size_x/2, som_size_y/2)")
    sigma_min = Parameter(0.1, "the neighbourhood radius never decays below this")
    sigma_max = Parameter(1.0, "the neighbourhood radius is never above this")
    sigma_decay = Parameter(0.9999, "the neighbourhood radius is multiplied by this after "
                            "each tick")
    seed = Parameter(None, "seed of the random initial weights; unset (or 0) gives a "
                     "different run every time", type="int")

    INPUT = Input("the input (an image or a matrix)")
    OUTPUT = Output("the activity of every unit at every receptive field, laid out by "
                    "output_type")
    OUTPUT_RED = Output("red part of a colour coding of the best unit at each receptive "
                        "field (its row), scaled by its activity")
    OUTPUT_GREEN = Output("green part of the colour coding (the best unit's column)")
    OUTPUT_BLUE = Output("blue part of the colour coding")
    WEIGHTS = Output("the weights: the receptive field of each unit, laid out as the map")
    ERROR = Output("RMS difference between the receptive fields and what their best units "
                   "represent", size="1")
    PROGRESS = Output("how much ERROR fell since the previous tick", size="1")
    STAT_DISTRIBUTION = Output("the fraction of all best-unit choices so far that went to "
                               "each unit")

    # the subclasses set these
    linear = False          # True: activity is the dot product and learning is Oja's rule
    streams = False         # True: upstreams / downstreams and TOP_DOWN / RECONSTRUCTION
    salience = False        # True: a SALIENCE output

    # --- build time ----------------------------------------------------------------------
    def _blocks(self):
        bx = getattr(self, "block_size_x", -1)
        by = getattr(self, "block_size_y", -1)
        bx = self.rf_size_x if bx is None or bx <= 0 else bx
        by = self.rf_size_y if by is None or by <= 0 else by
        sx = max(0, getattr(self, "span_size_x", 0) or 0)
        sy = max(0, getattr(self, "span_size_y", 0) or 0)
        return bx, by, sx, sy

    def _n_up(self):
        return max(1, getattr(self, "upstreams", 1) or 1) if self.streams else 1

    def _n_down(self):
        return max(1, getattr(self, "downstreams", 1) or 1) if self.streams else 0

    def _names(self, base, count):
        """Port names of the streams: ``base`` for one stream, base1..baseN for several."""
        return [base] if count == 1 else [f"{base}{i}" for i in range(1, count + 1)]

    def configure(self):
        for value, name in ((self.rf_size_x, "rf_size_x"), (self.rf_size_y, "rf_size_y"),
                            (self.som_size_x, "som_size_x"), (self.som_size_y, "som_size_y"),
                            (self.rf_inc_x, "rf_inc_x"), (self.rf_inc_y, "rf_inc_y")):
            if value < 1:
                raise ValueError(f"{name} must be at least 1")
        up, down = self._n_up(), self._n_down()
        if up > 1:
            for i in range(1, up + 1):
                self.add_input(f"INPUT{i}", description=f"input of stream {i}")
                for out in ("OUTPUT", "OUTPUT_RED", "OUTPUT_GREEN", "OUTPUT_BLUE"):
                    self.add_output(f"{out}{i}", description=f"{out} of stream {i}")
        if down > 1:
            for i in range(1, down + 1):
                self.add_input(f"TOP_DOWN{i}", optional=True,
                               description=f"top-down input of stream {i}")
                self.add_output(f"RECONSTRUCTION{i}",
                                description=f"reconstruction from TOP_DOWN{i}")
        som = (self.som_size_y, self.som_size_x)
        self.set_output_shape("WEIGHTS", (self.som_size_y * self.rf_size_y,
                                          self.som_size_x * self.rf_size_x))
        self.set_output_shape("STAT_DISTRIBUTION", som)

    def _geometry(self, in_shape):
        if len(in_shape) == 1:
            in_shape = (1, in_shape[0])
        rows, cols = in_shape[-2], in_shape[-1]
        bx, by, sx, sy = self._blocks()
        ext_y = field_extent(self.rf_size_y, by, sy)
        ext_x = field_extent(self.rf_size_x, bx, sx)
        if ext_y > rows or ext_x > cols:
            raise ValueError(f"the receptive field ({ext_y} x {ext_x}) is larger than the "
                             f"input ({rows} x {cols})")
        my = (rows - ext_y) // self.rf_inc_y + 1
        mx = (cols - ext_x) // self.rf_inc_x + 1
        return rows, cols, my, mx

    def set_sizes(self):
        up, down = self._n_up(), self._n_down()
        first = self._names("INPUT", up)[0]
        shape = self.input_shape(first)
        if shape is None:
            return
        if shape == ():
            raise ValueError(f"{first} is not connected")
        rows, cols, my, mx = self._geometry(shape)
        sy, sx = self.som_size_y, self.som_size_x
        outs = {"OUTPUT": (my * sy, mx * sx), "OUTPUT_RED": (my, mx),
                "OUTPUT_GREEN": (my, mx), "OUTPUT_BLUE": (my, mx)}
        for base, size in outs.items():
            self.set_output_shape(base, size)          # with several streams: stream 1
            if up > 1:
                for name in self._names(base, up):
                    self.set_output_shape(name, size)
        if self.salience:
            self.set_output_shape("SALIENCE", (my, mx))
        if down:
            self.set_output_shape("RECONSTRUCTION", tuple(shape))
            if down > 1:
                for name in self._names("RECONSTRUCTION", down):
                    self.set_output_shape(name, tuple(shape))

    # --- init ----------------------------------------------------------------------------
    def _arbor(self):
        ry, rx = self.rf_size_y, self.rf_size_x
        if not getattr(self, "use_arbor", False):
            return np.ones(ry * rx)
        y = (np.arange(ry) - (ry - 1) / 2) / ((ry + 0.5) / 2)
        x = (np.arange(rx) - (rx - 1) / 2) / ((rx + 0.5) / 2)
        return np.maximum(0.0, 1 - (y[:, None] ** 2 + x[None, :] ** 2)).ravel()

    def _indices(self, rows, cols, my, mx):
        bx, by, sx, sy = self._blocks()
        ry = np.arange(self.rf_size_y)
        rx = np.arange(self.rf_size_x)
        ry = ry + (ry // by) * sy
        rx = rx + (rx // bx) * sx
        r = (np.arange(my) * self.rf_inc_y)[:, None, None, None] + ry[None, None, :, None]
        c = (np.arange(mx) * self.rf_inc_x)[None, :, None, None] + rx[None, None, None, :]
        return (r * cols + c).reshape(my * mx, -1)            # (positions, field elements)

    def init(self):
        up, down = self._n_up(), self._n_down()
        self._inputs = [getattr(self, n) for n in self._names("INPUT", up)]
        rows, cols, my, mx = self._geometry(self._inputs[0].shape)
        for name, x in zip(self._names("INPUT", up), self._inputs):
            if x is None or x.size != rows * cols:
                self.fatal_error(f"{name} must be connected and have the size of the first "
                                 f"input ({rows} x {cols})")
        self._rows, self._cols, self._my, self._mx = rows, cols, my, mx
        self._idx = self._indices(rows, cols, my, mx)
        self._a = self._arbor().astype(np.float32)
        self._a_sum = float(self._a.sum()) or 1.0
        sy, sx = self.som_size_y, self.som_size_x
        n_units, n_elems = sy * sx, self.rf_size_y * self.rf_size_x
        gy, gx = np.divmod(np.arange(n_units), sx)
        dy = np.abs(gy[:, None] - gy[None, :]).astype(np.float64)
        dx = np.abs(gx[:, None] - gx[None, :]).astype(np.float64)
        if self.topology == "torus":
            dy = np.minimum(dy, sy - dy)
            dx = np.minimum(dx, sx - dx)
        self._grid_d2 = dy ** 2 + dx ** 2                     # (units, units)
        self._gy, self._gx = gy, gx
        self._radius = math.hypot(sx / 2, sy / 2)
        rng = np.random.default_rng(self.seed or None)
        self._rng = rng
        if self.linear:
            w = rng.standard_normal((n_units, n_elems))
            w /= np.linalg.norm(w, axis=1, keepdims=True)
        else:
            w = rng.uniform(0.0, 0.01, (n_units, n_elems))
        self._w = w.astype(np.float32)
        self._alpha = self._clip(self.alpha, self.alpha_min, self.alpha_max)
        self._sigma = self._clip(self.sigma, self.sigma_min, self.sigma_max)
        self._wins = np.zeros(n_units)
        self._error = 0.0
        self._warned = False
        # coverage of each input element by receptive fields, weighted by the arbor
        cover = np.bincount(self._idx.ravel(), weights=np.tile(self._a, my * mx),
                            minlength=rows * cols)
        self._inv_cover = np.divide(1.0, cover, out=np.zeros_like(cover),
                                    where=cover > 0).astype(np.float32)
        self._outputs = {base: [getattr(self, n) for n in self._names(base, up)]
                         for base in ("OUTPUT", "OUTPUT_RED", "OUTPUT_GREEN", "OUTPUT_BLUE")}
        if down:
            self._top_down = [getattr(self, n) for n in self._names("TOP_DOWN", down)]
            self._recon = [getattr(self, n) for n in self._names("RECONSTRUCTION", down)]
        self._load()
        self._write_weights()

    def _load(self):
        """Read a saved state; the subclasses say which file."""

    # --- tick ----------------------------------------------------------------------------
    def _patches(self, x):
        return x.reshape(-1)[self._idx]                       # (positions, field elements)

    def _match(self, X):
        """Activity (positions, units), best unit per position and its squared error."""
        a, w = self._a, self._w
        if self.linear:
            act = (X * a) @ w.T
            best = np.argmax(np.abs(act), axis=1)
            y = act[np.arange(len(best)), best]
            resid = (X - y[:, None] * w[best]) ** 2 @ a
            return act, best, resid / self._a_sum
        d2 = ((X * X) @ a)[:, None] - 2 * (X * a) @ w.T + ((w * w) @ a)[None, :]
        np.maximum(d2, 0, out=d2)
        best = np.argmin(d2, axis=1)
        mse = d2 / self._a_sum
        return 1 / (1 + mse), best, mse[np.arange(len(best)), best]

    def _learn(self, X, act, best):
        n = len(best)
        size = getattr(self, "learning_buffer_size", -1)
        if size is not None and 0 < size < n:                 # learn from a random sample
            pick = self._rng.choice(n, size, replace=False)
            X, act, best, n = X[pick], act[pick], best[pick], size
        sigma = self._sigma * self._radius
        h = np.exp(-self._grid_d2[best] / (2 * sigma * sigma)) if sigma > 0 else \
            (self._grid_d2[best] == 0).astype(np.float64)      # (positions, units)
        rate = self._alpha / n
        if self.linear:                                       # Oja's rule in the neighbourhood
            hy = h * act
            dw = hy.T @ X - (hy * act).sum(axis=0)[:, None] * self._w
        else:                                                 # Kohonen: towards the fields
            dw = h.T @ X - h.sum(axis=0)[:, None] * self._w
        self._w += (rate * dw * self._a).astype(np.float32)

    def _write_weights(self):
        sy, sx, ry, rx = self.som_size_y, self.som_size_x, self.rf_size_y, self.rf_size_x
        self.WEIGHTS[...] = self._w.reshape(sy, sx, ry, rx).transpose(0, 2, 1, 3).reshape(
            sy * ry, sx * rx)

    def _write_activity(self, out, act):
        sy, sx, my, mx = self.som_size_y, self.som_size_x, self._my, self._mx
        a = act.reshape(my, mx, sy, sx)
        if self.output_type == "separate":
            out[...] = a.transpose(2, 0, 3, 1).reshape(sy * my, sx * mx)
        else:
            out[...] = a.transpose(0, 2, 1, 3).reshape(my * sy, mx * sx)

    def _write_colours(self, red, green, blue, act, best):
        sy, sx = self.som_size_y, self.som_size_x
        m = np.abs(act[np.arange(len(best)), best])
        fy = self._gy[best] / (sy - 1) if sy > 1 else np.zeros(len(best))
        fx = self._gx[best] / (sx - 1) if sx > 1 else np.zeros(len(best))
        top = m.max(initial=0)
        scale = m / top if top > 0 else m
        shape = (self._my, self._mx)
        red[...] = (scale * fy).reshape(shape)
        green[...] = (scale * fx).reshape(shape)
        blue[...] = (scale * (1 - 0.5 * fy - 0.5 * fx)).reshape(shape)

    def _reconstruct(self, out, td):
        """RECONSTRUCTION from top-down activity td (positions, units)."""
        rows = np.arange(len(td))
        if self.linear:                   # the unit with the largest |td|, scaled by td
            best = np.argmax(np.abs(td), axis=1)
            fields = td[rows, best][:, None] * self._w[best]
        else:                             # the weights of the unit with the largest td
            best = np.argmax(td, axis=1)
            fields = np.where((td[rows, best] > 0)[:, None], self._w[best], 0)
        total = np.bincount(self._idx.ravel(), weights=(fields * self._a).ravel(),
                            minlength=self._rows * self._cols)
        out[...] = (total * self._inv_cover).reshape(out.shape)

    def _top_down_activity(self, td):
        """Rearrange a TOP_DOWN array laid out like OUTPUT into (positions, units)."""
        sy, sx, my, mx = self.som_size_y, self.som_size_x, self._my, self._mx
        if td.size != my * mx * sy * sx:
            return None
        if self.output_type == "separate":
            a = td.reshape(sy, my, sx, mx).transpose(1, 3, 0, 2)
        else:
            a = td.reshape(my, sy, mx, sx).transpose(0, 2, 1, 3)
        return a.reshape(my * mx, sy * sx)

    def learning(self):
        return True

    def tick(self):
        learn = self.learning()
        errors, first = [], None
        for s, x in enumerate(self._inputs):
            X = self._patches(x)
            act, best, err = self._match(X)
            if learn:
                self._learn(X, act, best)
            self._wins += np.bincount(best, minlength=self._wins.size)
            errors.append(err)
            self._write_activity(self._outputs["OUTPUT"][s], act)
            self._write_colours(self._outputs["OUTPUT_RED"][s], self._outputs["OUTPUT_GREEN"][s],
                                self._outputs["OUTPUT_BLUE"][s], act, best)
            if s == 0:
                first = (act, best)
                if self.salience:
                    self.SALIENCE[...] = act.sum(axis=1).reshape(self._my, self._mx)
        if len(self._inputs) > 1:                     # the single-stream ports mirror stream 1
            for base in self._outputs:
                getattr(self, base)[...] = self._outputs[base][0]
        if self._n_down():
            for td, out in zip(self._top_down, self._recon):
                a = None if td is None else self._top_down_activity(td)
                if td is not None and a is None and not self._warned:
                    self._warned = True
                    self.warning(f"TOP_DOWN has {td.size} elements; OUTPUT has "
                                 f"{self.OUTPUT.size}; the best units are used instead")
                if a is None:                         # unconnected: the best units' fields
                    act, best = first
                    a = np.zeros_like(act)
                    rows = np.arange(len(best))
                    a[rows, best] = act[rows, best] if self.linear else 1
                self._reconstruct(out, a)
            if len(self._recon) > 1:
                self.RECONSTRUCTION[...] = self._recon[0]
        error = math.sqrt(float(np.mean(np.concatenate(errors))))
        self.PROGRESS[0] = self._error - error if self.clock.tick > 0 else 0.0
        self.ERROR[0] = self._error = error
        total = self._wins.sum()
        self.STAT_DISTRIBUTION[...] = (self._wins / total).reshape(
            self.som_size_y, self.som_size_x) if total else 0
        self._write_weights()
        if learn:
            self._alpha = self._clip(self._alpha * self.alpha_decay, self.alpha_min,
                                     self.alpha_max)
            self._sigma = self._clip(self._sigma * self.sigma_decay, self.sigma_min,
                                     self.sigma_max)

    @staticmethod
    def _clip(value, low, high):
        return float(min(max(value, low), max(high, low)))

    # --- saved state ---------------------------------------------------------------------
    def _save_text(self, filename, weights_only):
        values = [self._w.ravel()]
        if not weights_only:
            values.append(np.array([self._alpha, self._sigma]))
            values.append(self._wins)
        np.savetxt(resolve(self, filename), np.concatenate(values), fmt="%.9g")

    def _load_text(self, filename, weights_only):
        path = resolve(self, filename)
        try:
            data = np.loadtxt(path, ndmin=1)
        except OSError:
            self.warning(f"cannot read the state file {path}; starting from random weights")
            return
        n = self._w.size
        if data.size < n:
            self.warning(f"{path} holds {data.size} values; {n} weights are needed")
            return
        self._w[...] = data[:n].reshape(self._w.shape)
        rest = data[n:]
        if not weights_only and rest.size == 2 + self._wins.size:
            self._alpha, self._sigma = float(rest[0]), float(rest[1])
            self._wins[...] = rest[2:]


class StreamSOM(SOMBase):
    """Base of CSOM and CSOM_PCA: several input streams sharing one map, top-down
    reconstruction, and receptive fields made of blocks with gaps."""

    block_size_x = Parameter(-1, "width of the blocks a receptive field is divided into "
                             "(-1: the whole field)")
    block_size_y = Parameter(-1, "height of the blocks a receptive field is divided into "
                             "(-1: the whole field)")
    span_size_x = Parameter(0, "input columns skipped between the blocks of a receptive field")
    span_size_y = Parameter(0, "input rows skipped between the blocks of a receptive field")
    learning_buffer_size = Parameter(-1, "learn from this many receptive fields drawn at "
                                     "random each tick (-1: from all)")
    upstreams = Parameter(1, "number of input streams sharing the map; with more than one the "
                          "ports are INPUT1, OUTPUT1, OUTPUT_RED1, ... and INPUT2, ...")
    downstreams = Parameter(1, "number of top-down streams; with more than one the ports are "
                            "TOP_DOWN1, RECONSTRUCTION1, ...")

    INPUT = Input("the input (an image or a matrix); with upstreams > 1 the inputs are "
                  "INPUT1, INPUT2, ... instead", optional=True)
    TOP_DOWN = Input("activity laid out like OUTPUT (from this map or a higher level) to "
                     "reconstruct the input from", optional=True)
    RECONSTRUCTION = Output("the input reconstructed from TOP_DOWN (from the best units "
                            "when it is not connected), averaged where fields overlap")

    streams = True
