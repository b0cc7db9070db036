"""MatrixFunctionTestModule: a self-test of the array operations a module author uses on its
own buffers through the module API (this project's counterpart of Ikaros 3's matrix-library
self-test, TESTS.md rows 70-76 and 79)."""
import numpy as np

from ikaros.dynamic import DynamicArray
from ikaros.module import Input, Output, Parameter
from ikaros.modules.io._images import from_uint8, to_uint8
from ikaros.modules.vision import _cv as images

from ikaros.testsupport._internal import InternalModule

TESTS = "reductions,scalar,elementwise,linalg,image,submatrix,contracts,hotspots"


class Mismatch(Exception):
    """The first check of a test that did not give its expected value."""


def expect(what: str, got, expected, tolerance: float = 0.0) -> None:
    """Raise ``Mismatch`` unless ``got`` has the shape and values of ``expected`` (exactly,
    or within ``tolerance``). Expected values are rounded to ``got``'s float type first."""
    got = np.asarray(got)
    wanted = np.asarray(expected, dtype=got.dtype if got.dtype.kind == "f" else None)
    if got.shape != wanted.shape or not np.allclose(got, wanted, rtol=0.0, atol=tolerance):
        raise Mismatch(f"{what} is {got.tolist()}, expected {wanted.tolist()}")


def raises(what: str, error: type, action, message_part: str) -> None:
    """Raise ``Mismatch`` unless ``action()`` raises ``error`` with ``message_part`` in its
    message."""
    try:
        action()
    except error as e:
        if message_part not in str(e):
            raise Mismatch(f"{what} raised {e!r}, without {message_part!r}") from None
        return
    raise Mismatch(f"{what} was not caught (no {error.__name__})")


class MatrixFunctionTestModule(InternalModule):
    """Checks, in ``init``, one group of array operations on its float32 buffers (``test``)
    with exact expected values, and prints ``MATRIX TEST <test> OK``; the first mismatch is
    a fatal error naming it. OUTPUT is 3x4, COLUMNS 4, IMAGE a 3x4x5 colour image and GRAY
    4x5. When OUTPUT is connected to INPUT (delay 1), ``submatrix`` checks on INPUT, in
    every tick, the values written through views of OUTPUT in ``init``, and ``contracts``
    checks on tick 0 that an array put in place of OUTPUT in ``init`` was not read; OK is
    then printed after tick 0."""

    test = Parameter("reductions", "the group of operations to check", options=TESTS)
    INPUT = Input("OUTPUT again, for the submatrix and contracts tests", optional=True)
    OUTPUT = Output("the 3x4 buffer the checks write", shape="3,4")
    COLUMNS = Output("a 4-vector the checks write", shape="4")
    IMAGE = Output("a colour image (3, rows, cols)", shape="3,4,5")
    GRAY = Output("a gray image (rows, cols)", shape="4,5")

    def init(self):
        self._run(getattr(self, f"_{self.test}"), report=not self._checks_input())

    def tick(self):
        if not self._checks_input():
            return
        check = self._views_read if self.test == "submatrix" else self._contracts_read
        self._run(check, report=self.clock.tick == 0)

    def _checks_input(self) -> bool:
        return self.INPUT is not None and self.test in ("submatrix", "contracts")

    def _run(self, check, report: bool) -> None:
        """Runs ``check``: a mismatch is a fatal error; else prints OK if ``report``."""
        try:
            check()
        except Mismatch as e:
            self.fatal_error(f"MATRIX TEST {self.test} FAILED: {e}")
        else:
            if report:
                self.print(f"MATRIX TEST {self.test} OK")

    def _fill(self) -> np.ndarray:
        """OUTPUT = 0 1 2 3 / 4 5 6 7 / 8 9 10 11, written in place."""
        self.OUTPUT[...] = np.arange(12).reshape(3, 4)
        return self.OUTPUT

    def _reductions(self):
        m = self._fill()
        expect("sum", m.sum(), 66)
        expect("sum over axis 0", m.sum(axis=0), [12, 15, 18, 21])
        expect("sum over axis 1", m.sum(axis=1), [6, 22, 38])
        expect("min, max", [m.min(), m.max()], [0, 11])
        expect("min over axis 1", m.min(axis=1), [0, 4, 8])
        expect("max over axis 0", m.max(axis=0), [8, 9, 10, 11])
        expect("argmax", m.argmax(), 11)
        expect("argmin over axis 0", m.argmin(axis=0), [0, 0, 0, 0])
        expect("argmax over axis 1", m.argmax(axis=1), [3, 3, 3])
        expect("mean", m.mean(), 5.5)
        expect("mean over axis 1", m.mean(axis=1), [1.5, 5.5, 9.5])
        expect("product of row 1", m[1].prod(), 840)
        expect("cumulative sum of row 0", np.cumsum(m[0]), [0, 1, 3, 6])
        np.sum(m, axis=0, out=self.COLUMNS)
        expect("sum over axis 0 into COLUMNS (out=)", self.COLUMNS, [12, 15, 18, 21])
        np.max(m, axis=0, out=self.COLUMNS)
        expect("max over axis 0 into COLUMNS (out=)", self.COLUMNS, [8, 9, 10, 11])
        expect("count of values above 5", np.count_nonzero(m > 5), 6)
        expect("sum of an all-zero buffer", np.zeros_like(m).sum(), 0)

    def _scalar(self):
        m = self.OUTPUT
        expect("shape, size, rank", [*m.shape, m.size, m.ndim], [3, 4, 12, 2])
        if m.dtype != np.float32:
            raise Mismatch(f"the dtype of OUTPUT is {m.dtype}, expected float32")
        m.fill(2.5)
        expect("fill(2.5)", m, np.full((3, 4), 2.5))
        m *= 2
        m += 1
        m -= 0.5
        m /= 2
        expect("(2.5 * 2 + 1 - 0.5) / 2 in place", m, np.full((3, 4), 2.75))
        m[1, 2] = 7
        expect("one element set", [m[1, 2], m.item(6), m.sum()], [7, 7, 2.75 * 11 + 7])
        flat = m.reshape(-1)
        if not np.shares_memory(flat, m):
            raise Mismatch("reshape(-1) of OUTPUT is a copy, not a view")
        flat[:] = np.arange(12)
        expect("OUTPUT written through its flat view", m[2], [8, 9, 10, 11])
        expect("reshape(4, 3)", m.reshape(4, 3)[3], [9, 10, 11])
        expect("transpose", m.T.shape, (4, 3))
        expect("ravel order", m.T.ravel()[:3], [0, 4, 8])
        expect("a float32 scalar", m[0, 1] / np.float32(3), np.float32(1) / np.float32(3))

    def _elementwise(self):
        m = self._fill()
        row = np.array([1, -1, 2, -2], np.float32)
        col = np.array([[10], [20], [30]], np.float32)
        np.add(m, row, out=m)
        expect("add a row (broadcast)", m[0], [1, 0, 4, 1])
        np.add(m, col, out=m)
        expect("add a column (broadcast)", m[:, 0], [11, 25, 39])
        self._fill()
        expect("m * m", (m * m)[2], [64, 81, 100, 121])
        expect("m - 5", (m - 5)[0], [-5, -4, -3, -2])
        expect("m / 2", (m / 2)[1], [2, 2.5, 3, 3.5])
        expect("abs(m - 6)", np.abs(m - 6)[0], [6, 5, 4, 3])
        expect("sqrt(m * m)", np.sqrt(m * m), np.arange(12).reshape(3, 4))
        expect("exp(0), log(1)", [np.exp(m[0, 0]), np.log(m[0, 1])], [1, 0])
        np.clip(m, 2, 9, out=m)
        expect("clip to 2..9 in place", m.ravel(), [2, 2, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9])
        self._fill()
        np.maximum(m - 5, 0, out=m)
        expect("max(m - 5, 0) in place", m[1], [0, 0, 1, 2])
        self._fill()
        expect("minimum", np.minimum(m, 3)[2], [3, 3, 3, 3])
        expect("where", np.where(m % 2 == 0, m, -1)[0], [0, -1, 2, -1])
        expect("comparison", (m >= 10).sum(), 2)
        expect("sign", np.sign(m - 1)[0], [-1, 0, 1, 1])
        expect("floor, round", [np.floor(np.float32(2.7)), np.round(np.float32(2.5))], [2, 2])

    def _linalg(self):
        a = np.array([[1, 2], [3, 4]], np.float32)
        b = np.array([[5, 6], [7, 8]], np.float32)
        product = self.OUTPUT[:2, :2]
        np.matmul(a, b, out=product)
        expect("[[1,2],[3,4]] @ [[5,6],[7,8]] into a view of OUTPUT", self.OUTPUT[:2, :2],
               [[19, 22], [43, 50]])
        expect("matrix times vector", a @ np.array([1, 1], np.float32), [3, 7])
        expect("dot of two vectors", np.dot(a[0], a[1]), 11)
        expect("outer product", np.outer([1, 2], [3, 4]), [[3, 4], [6, 8]])
        expect("transpose", a.T, [[1, 3], [2, 4]])
        expect("inverse of [[2,1],[1,1]]", np.linalg.inv(np.array([[2, 1], [1, 1]],
                                                                  np.float32)),
               [[1, -1], [-1, 2]], 1e-6)
        expect("inverse of [[4,7],[2,6]]", np.linalg.inv(np.array([[4, 7], [2, 6]],
                                                                  np.float32)),
               [[0.6, -0.7], [-0.2, 0.4]], 1e-6)
        expect("solve [[2,1],[1,3]] x = [3,5]",
               np.linalg.solve(np.array([[2, 1], [1, 3]], np.float32),
                               np.array([3, 5], np.float32)), [0.8, 1.4], 1e-6)
        expect("determinant", np.linalg.det(a), -2, 1e-5)
        expect("trace", np.trace(a), 5)
        expect("identity", np.eye(2, dtype=np.float32) @ b, b)
        expect("norm of [3, 4]", np.linalg.norm(np.array([3, 4], np.float32)), 5)
        expect("pseudo-inverse of [[1],[1]]", np.linalg.pinv(np.ones((2, 1), np.float32)),
               [[0.5, 0.5]], 1e-6)

    def _image(self):
        rgb, gray = self.IMAGE, self.GRAY
        expect("IMAGE is colour, GRAY is not", [images.is_colour(rgb.shape),
                                                images.is_colour(gray.shape)], [1, 0])
        red, green, blue = images.planes(rgb)
        red[...], green[...], blue[...] = 0.3, 0.6, 0.9
        expect("IMAGE's planes written as views", rgb[:, 2, 3], [0.3, 0.6, 0.9])
        expect("planes of a gray image", len(images.planes(gray)), 1)
        intensity = images.GrayImage(rgb)()
        expect("intensity (R + G + B) / 3", intensity[0, 0], 0.6, 1e-6)
        if images.GrayImage(gray)() is not gray:
            raise Mismatch("the gray version of a gray image is a copy, not the image")
        expect("with_size of a colour image", images.with_size(rgb.shape, 2, 2), (3, 2, 2))
        expect("with_size of a gray image", images.with_size(gray.shape, 2, 2), (2, 2))
        expect("shrunk by a 3x3 kernel", images.shrunk(rgb.shape, 3), (3, 2, 3))
        gray[...] = np.arange(20).reshape(4, 5) / 20
        images.interior(gray, 1, 1, 2, 3)[...] = 1
        expect("interior view written", gray[1:3, 1:4].sum() + gray[0].sum(), 6 + 0.5,
               1e-6)
        expect("pixel_of (0.5, 0.5) in 4x5", images.pixel_of(0.5, 0.5, 4, 5), (2, 2))
        expect("pixel_of (1, 1) clamped", images.pixel_of(1.0, 1.0, 4, 5), (3, 4))
        expect("position_of (0, 0) in 4x5", images.position_of(0, 0, 4, 5), (0.1, 0.125))
        expect("to 8-bit levels", to_uint8(np.array([-1, 0, 0.5, 1, 2, np.nan])),
               [0, 0, 128, 255, 255, 0])
        expect("from 8-bit levels and back", to_uint8(from_uint8(np.arange(256,
                                                                           dtype=np.uint8))),
               np.arange(256))
        raises("a 2x3x4 array taken as an image", ValueError,
               lambda: images.check_image((2, 3, 4)), "(3, rows, cols)")

    def _submatrix(self):
        m = self.OUTPUT
        m.fill(0)
        m[0] = [1, 2, 3, 4]                  # a row
        m[:, 3] += 10                         # a column
        block = m[1:, :2]                     # a 2x2 block
        block[...] = [[5, 6], [7, 8]]
        np.multiply(m[2], 2, out=m[2])       # a ufunc writing into a row
        m[1, 2:3] = 9                         # a one-element slice
        m[::2, 2] -= 1                        # a strided view
        expect("OUTPUT written through views", m, SUBMATRIX)
        expect("sum of a row view", m[1].sum(), 30)
        expect("max of a column view", m[:, 3].max(), 20)
        expect("a block's transpose", m[1:, :2].T, [[5, 14], [6, 16]])

    def _views_read(self):
        expect("INPUT (the OUTPUT written through views)", self.INPUT, SUBMATRIX)

    def _contracts(self):
        m = self.OUTPUT
        raises("a 5-vector written into the 3x4 OUTPUT", ValueError,
               lambda: m.__setitem__(Ellipsis, np.zeros(5)), "(3,4)")
        raises("a 4x3 result written into OUTPUT with out=", ValueError,
               lambda: np.add(np.zeros((4, 3)), 1, out=m), "(3,4)")
        raises("row 3 of the 3x4 OUTPUT", IndexError, lambda: m.__setitem__(3, 0),
               "out of bounds")
        raises("a reshape of OUTPUT to 5x3", ValueError, lambda: m.reshape(5, 3), "size 12")
        raises("the shape of an output that does not exist", KeyError,
               lambda: self.set_output_shape("NO_SUCH_OUTPUT", 3), "no output named")
        dynamic = DynamicArray((3, 2))
        raises("a dynamic array resized beyond its capacity", ValueError,
               lambda: dynamic.resize((4, 2)), "does not fit the capacity")
        expect("OUTPUT after the refused writes", m, np.zeros((3, 4)))

    def _contracts_read(self):
        expect("INPUT (OUTPUT after the refused writes)", self.INPUT, np.zeros((3, 4)))

    def _hotspots(self):
        m = self._fill()
        w = np.arange(4, dtype=np.float32)
        rows = np.empty(3, np.float32)
        np.dot(m, w, out=rows)
        expect("matrix-vector product with out=", rows, [14, 38, 62])
        np.matmul(w, m.T, out=rows)
        expect("vector-matrix product with out=", rows, [14, 38, 62])
        np.copyto(self.COLUMNS, m[1])
        expect("copyto a row", self.COLUMNS, [4, 5, 6, 7])
        self.COLUMNS[:] = m[:, 1:3].sum(axis=None)
        expect("a block's sum broadcast into COLUMNS", self.COLUMNS, [33, 33, 33, 33])
        m *= np.float32(0.5)
        expect("scale in place", m[2], [4, 4.5, 5, 5.5])
        np.subtract(m, m.mean(axis=1, keepdims=True), out=m)
        expect("rows centred in place", m[0], [-0.75, -0.25, 0.25, 0.75])
        expect("take with indices", np.take(m[2], [3, 0]), [0.75, -0.75])
        self._fill()
        m[m > 8] = 0
        expect("masked write", m[2], [8, 0, 0, 0])
        np.tanh(np.zeros(4, np.float32), out=self.COLUMNS)
        expect("tanh(0)", self.COLUMNS, [0, 0, 0, 0])
        expect("argmax of a row", int(np.argmax(m[1])), 3)
        expect("sum of an outer product", np.outer([1, 2, 3], [1, 0, 0, 1]).sum(), 12)


#: OUTPUT after the submatrix test's writes through views
SUBMATRIX = [[1, 2, 2, 14], [5, 6, 9, 10], [14, 16, -1, 20]]
