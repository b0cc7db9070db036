"""Trainer: feeds a learning module from data sets and measures its test error."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from .._crand import random_rows


class Trainer(Module):
    """Feeds a learning module from a data set: each row of TRAINING_DATA_X is an example
    input and the same row of TRAINING_DATA_Y its target (a 1-D data input is a single
    example). On every tick one training example goes out on TRAIN_X and TRAIN_Y, taken in
    ``sequential`` order (wrapping around) or in ``random`` order, and each example is held
    for ``repetitions`` ticks. ``crossvalidation`` picks the test examples sent on TEST_X:
    ``none`` sends none (TEST_X stays 0 and so does ERROR); ``all`` tests on the example being
    trained on; ``even`` tests on the even-numbered rows (0, 2, ...) and trains only on the
    odd ones; ``odd`` tests on the odd rows and trains on the even ones; ``input`` trains on
    all rows and tests on TESTING_DATA_X / TESTING_DATA_Y. TEST_Y takes the learner's answer:
    on each tick ERROR is the Euclidean distance between TEST_Y and the target of the test
    example sent on the previous tick (0 on tick 0), which is right when TEST_X reaches the
    learner with a delay of 1 and its answer comes back with a delay of 0. The outputs are 0
    in init and the first examples go out on tick 0. Without TRAINING_DATA_Y, TRAIN_Y is one
    element that stays 0.

    The random order draws the row as rand() % rows from the C library's rand(), as Ikaros 2
    does: with ``seed`` unset (or 0) an Ikaros 2 file gets the original's sequence (glibc's,
    from its start, shared with the other modules of the network that draw from it), so the
    order is the same on every run and the same as the original's when no other module
    draws (the golden files show it). The first example is row 0. With testing by even, odd
    or input rows, the test row is drawn after the training row (this project's reading).
    A seed above 0 gives the same order for the same seed, and a seed below 0 (or an unset
    seed in an Ikaros 3 file) a different order on every run. The class is not in
    Ikaros 3."""

    order = Parameter("random", "random or sequential order of presentation",
                      options="random/sequential")
    crossvalidation = Parameter("none", "the test examples: none, all (the training "
                                "examples), even or odd rows of the training data, or input "
                                "(the TESTING_DATA inputs)", options="none/all/even/odd/input")
    repetitions = Parameter(1, "the number of ticks each example is held", type="int")
    seed = Parameter(None, "seed of the random order; unset or 0: Ikaros 2's rand() "
                     "sequence (Ikaros 3 file: a different run every time); below 0: a "
                     "different run every time", type="int")
    TRAINING_DATA_X = Input("the training inputs, one example per row")
    TRAINING_DATA_Y = Input("the training targets, one example per row", optional=True)
    TESTING_DATA_X = Input("the test inputs, one example per row (crossvalidation input)",
                           optional=True)
    TESTING_DATA_Y = Input("the test targets, one example per row (crossvalidation input)",
                           optional=True)
    TEST_Y = Input("the learner's output for the last TEST_X", optional=True)
    TRAIN_X = Output("the training input for the learner")
    TRAIN_Y = Output("the training target for the learner")
    TEST_X = Output("the test input for the learner")
    ERROR = Output("the distance between TEST_Y and the target of the last test example",
                   size="1")

    def set_sizes(self):
        x, y = self.input_shape("TRAINING_DATA_X"), self.input_shape("TRAINING_DATA_Y")
        if x is not None:
            width = x[-1] if len(x) > 1 else int(np.prod(x))
            if len(x) > 2:
                width = int(np.prod(x[1:]))
            self.set_output_shape("TRAIN_X", (width,))
            self.set_output_shape("TEST_X", (width,))
        if y is not None:
            width = 1 if y == () else (int(np.prod(y[1:])) if len(y) > 1 else int(np.prod(y)))
            self.set_output_shape("TRAIN_Y", (width,))

    @staticmethod
    def _rows(data, width):
        return data.reshape(-1, width) if data is not None else None

    def init(self):
        nx, ny = self.TRAIN_X.size, self.TRAIN_Y.size
        self._x = self._rows(self.TRAINING_DATA_X, nx)
        count = len(self._x)
        self._y = self._rows(self.TRAINING_DATA_Y, ny)
        if self._y is None:
            self._y = np.zeros((count, ny), np.float32)
        if len(self._y) != count:
            raise ValueError(f"TRAINING_DATA_X has {count} rows but TRAINING_DATA_Y has "
                             f"{len(self._y)}")
        mode = self.crossvalidation
        all_rows = np.arange(count)
        self._train_rows = {"even": all_rows[1::2], "odd": all_rows[0::2]}.get(mode, all_rows)
        self._test_x, self._test_y = self._x, self._y
        self._test_rows = {"even": all_rows[0::2], "odd": all_rows[1::2]}.get(mode, all_rows)
        if mode == "input":
            if self.TESTING_DATA_X is None or self.TESTING_DATA_Y is None:
                raise ValueError("crossvalidation is input but TESTING_DATA_X or "
                                 "TESTING_DATA_Y is not connected")
            self._test_x = self._rows(self.TESTING_DATA_X, nx)
            self._test_y = self._rows(self.TESTING_DATA_Y, ny)
            if len(self._test_x) != len(self._test_y):
                raise ValueError("TESTING_DATA_X and TESTING_DATA_Y have different numbers "
                                 "of rows")
            self._test_rows = np.arange(len(self._test_x))
        elif self.TESTING_DATA_X is not None:
            self.warning("TESTING_DATA_X is ignored since crossvalidation is not input")
        if len(self._train_rows) == 0 or len(self._test_rows) == 0:
            raise ValueError("there are too few examples for this crossvalidation")
        self._testing = mode != "none"
        self._draw = random_rows(self)
        self._held = 0
        self._train_i = self._test_i = 0            # positions in _train_rows / _test_rows
        self._target = np.zeros(ny, np.float32)     # target of the test example sent last
        self._sent = False
        self.ERROR[...] = 0

    def _send(self):
        row = self._train_rows[self._train_i]
        self.TRAIN_X[...] = self._x[row]
        self.TRAIN_Y[...] = self._y[row]
        if not self._testing:
            return
        if self.crossvalidation == "all":
            test = row
        else:
            test = self._test_rows[self._test_i]
        self.TEST_X[...] = self._test_x[test]
        self._target[...] = self._test_y[test]

    def _advance(self):
        self._held += 1
        if self._held < max(1, self.repetitions):
            return
        self._held = 0
        if self.order == "random":
            self._train_i = self._draw(len(self._train_rows))
            if self.crossvalidation in ("even", "odd", "input"):
                self._test_i = self._draw(len(self._test_rows))
        else:
            self._train_i = (self._train_i + 1) % len(self._train_rows)
            self._test_i = (self._test_i + 1) % len(self._test_rows)

    def tick(self):
        if not self._sent:
            self._sent = True
            self._send()
            return
        if self._testing and self.TEST_Y is not None:
            answer = self.TEST_Y.reshape(-1)
            if answer.size != self._target.size:
                self.error(f"TEST_Y has {answer.size} elements but the targets have "
                           f"{self._target.size}")
                self._testing = False
            else:
                diff = answer.astype(np.float64) - self._target
                self.ERROR[0] = np.sqrt(diff @ diff)
        self._advance()
        self._send()
