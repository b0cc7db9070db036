"""LinearAssociator: learns a linear map from training pairs."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class LinearAssociator(Module):
    """Learns a linear map MATRIX from T-INPUT to T-OUTPUT and outputs OUTPUT = MATRIX . INPUT
    (computed after this tick's learning), as Ikaros 2 does (the class is not in Ikaros 3).
    MATRIX starts at zero, with one row per element of T-OUTPUT and one column per element
    of T-INPUT. On every tick the pair T-INPUT, T-OUTPUT is put in a memory of
    ``memory_max`` samples (once it is full, a random stored sample is replaced). In
    ``gradient_descent`` mode the module then learns the pair of this tick once and goes
    ``memory_training`` times through the stored samples; each step computes the error
    e = target - MATRIX . x, smooths it as m = beta * m + (1 - beta) * e (momentum, kept from
    step to step) and adds alpha * outer(m, x) to MATRIX. ERROR is the mean Euclidean norm of
    the errors met in the last pass through the memory (of the first step when
    memory_training is 0) and CONFIDENCE is 1 - ERROR. With the default memory of one sample
    and one pass this is two steps on the pair of the tick, which is what Ikaros 2 computes
    (the golden files show it, and that ERROR is measured between the two); how Ikaros 2
    orders the steps for a larger memory, which sample it replaces, and its ``LMS`` mode are
    not shown by any reference: here ``LMS`` sets MATRIX to the least-squares solution over
    the stored samples (the least-norm one when they do not fix it), so memory_max should be
    well above the input size, and ERROR is the mean norm of its errors.

    Ikaros 2 ignores LEARNING (the golden files show it learning with LEARNING below 0),
    and so does this class by default. ``use_learning="yes"`` (this project's) stores and
    learns only on ticks where LEARNING's first element is above 0, that element scaling
    alpha; ERROR and CONFIDENCE then keep their values between learning ticks. The same
    ``seed`` gives the same choice of replaced samples."""

    mode = Parameter("gradient_descent", "gradient_descent: learn sample by sample; LMS: set "
                     "the least-squares solution over the stored samples",
                     options="gradient_descent/LMS")
    alpha = Parameter(0.1, "the learning rate (gradient descent)")
    beta = Parameter(0.0, "the momentum rate, 0..1 (gradient descent)")
    memory_max = Parameter(1, "the number of training samples kept", type="int")
    memory_training = Parameter(1, "the number of passes through the stored samples on each "
                                "tick (gradient descent)", type="int")
    seed = Parameter(None, "seed of the random generator that picks the sample to replace; "
                     "unset (or 0) gives a different run every time", type="int")
    use_learning = Parameter(False, "no: LEARNING is ignored, as in Ikaros 2; yes: learning "
                             "happens while its first element is above 0, which scales alpha")
    LEARNING = Input("with use_learning: learning happens while its first element is above 0, "
                     "which also scales alpha", optional=True)
    INPUT = Input("the input mapped to OUTPUT")
    T_INPUT = Input("the training input", name="T-INPUT")
    T_OUTPUT = Input("the training target", name="T-OUTPUT")
    OUTPUT = Output("MATRIX . INPUT", size_set="T-OUTPUT")
    MATRIX = Output("the learned map: one row per target element, one column per input "
                    "element", size_set_x="T-INPUT", size_set_y="T-OUTPUT")
    ERROR = Output("the mean norm of the training errors", size="1")
    CONFIDENCE = Output("1 - ERROR", size="1")

    def init(self):
        n, m = self.T_INPUT.size, self.T_OUTPUT.size
        if self.INPUT.size != n:
            raise ValueError(f"INPUT and T-INPUT must have the same size ({self.INPUT.size} "
                             f"!= {n})")
        if self.MATRIX.size != m * n:
            raise ValueError(f"MATRIX has shape {self.MATRIX.shape}, expected {(m, n)}")
        self._w = self.MATRIX.reshape(m, n)
        if self.mode == "LMS" and self.memory_max <= 1:
            self.warning("mode is LMS but memory_max is 1")
        self._rng = np.random.default_rng(self.seed or None)
        size = max(1, self.memory_max)
        self._mem_x = np.zeros((size, n), np.float32)
        self._mem_y = np.zeros((size, m), np.float32)
        self._used = 0
        self._momentum = np.zeros(m, np.float32)
        self._w[...] = 0
        self.OUTPUT[...] = 0
        self.ERROR[...] = 0
        self.CONFIDENCE[...] = 1

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._w[...] = 0
            self._momentum[...] = 0
            self._used = 0

    def _remember(self):
        slot = self._used
        if slot < len(self._mem_x):
            self._used += 1
        else:
            slot = int(self._rng.integers(len(self._mem_x)))
        self._mem_x[slot] = self.T_INPUT.reshape(-1)
        self._mem_y[slot] = self.T_OUTPUT.reshape(-1)

    def _pass(self, xs, ys, alpha, beta):
        """One gradient step on each sample in turn; the norms of the errors met."""
        w = self._w
        norms = np.empty(len(xs))
        for i, (x, y) in enumerate(zip(xs, ys)):
            e = y - w @ x
            norms[i] = np.sqrt(e @ e)
            self._momentum *= beta
            self._momentum += (1 - beta) * e
            w += alpha * np.outer(self._momentum, x)
        return norms

    def tick(self):
        rate = 1.0
        if self.use_learning and self.LEARNING is not None:
            rate = float(self.LEARNING.reshape(-1)[0])
        if rate > 0:
            self._remember()
            xs, ys = self._mem_x[:self._used], self._mem_y[:self._used]
            w = self._w
            if self.mode == "LMS":
                w[...] = np.linalg.lstsq(xs.astype(np.float64), ys.astype(np.float64),
                                         rcond=None)[0].T
                errors = ys - xs @ w.T
                error = np.mean(np.sqrt(np.sum(errors * errors, axis=1)))
            else:
                alpha, beta = np.float32(self.alpha * rate), np.float32(self.beta)
                norms = self._pass(self.T_INPUT.reshape(1, -1), self.T_OUTPUT.reshape(1, -1),
                                   alpha, beta)
                for _ in range(max(0, self.memory_training)):
                    norms = self._pass(xs, ys, alpha, beta)
                error = np.mean(norms)
            self.ERROR[0] = error
            self.CONFIDENCE[0] = 1 - self.ERROR[0]
        np.dot(self._w, self.INPUT.reshape(-1), out=self.OUTPUT.reshape(-1))
