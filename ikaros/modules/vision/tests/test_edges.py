"""Tests of the edge detectors and feature detectors on synthetic images with known edges,
corners and circles."""
import numpy as np
import pytest
from scipy import ndimage, signal

import ikaros
from ikaros.testing import load_body
from vision_models import literal, outputs, run

RNG = np.random.default_rng(11)
GRAY = RNG.random((10, 12)).astype(np.float32)


def square(size=24, lo=6, hi=18, value=1.0):
    """A bright square: rows and columns lo..hi-1 are ``value`` on 0."""
    image = np.zeros((size, size), np.float32)
    image[lo:hi, lo:hi] = value
    return image


def boundary(size=24, lo=6, hi=18):
    """Pixels within one pixel of the square's boundary (inside or outside)."""
    inside = square(size, lo, hi) > 0
    square3 = np.ones((3, 3), bool)
    return ndimage.binary_dilation(inside, square3) & ~ndimage.binary_erosion(inside, square3)


def correlate(image, kernel):
    return signal.correlate2d(image.astype(np.float64), kernel, mode="valid")


SOBEL_X = np.array([[-1, 0, 1], [-2, 0, 2], [-1, 0, 1]])


@pytest.mark.parametrize("kind, expected", [
    ("sqrt", lambda dx, dy: np.hypot(dx, dy)),
    ("abs", lambda dx, dy: abs(dx) + abs(dy)),
    ("dx", lambda dx, dy: dx),
    ("dy", lambda dx, dy: dy),
    ("abs(dx)", lambda dx, dy: abs(dx)),
    ("abs(dy)", lambda dx, dy: abs(dy)),
])
def test_sobel_types(tmp_path, kind, expected):
    """dx and dy are convolutions with the Sobel kernels, as Ikaros 2's golden outputs."""
    out, = outputs(tmp_path, "SobelEdgeDetector", {"INPUT": GRAY}, "OUTPUT", type=kind)
    dx = signal.convolve2d(GRAY.astype(np.float64), SOBEL_X, mode="valid")
    dy = signal.convolve2d(GRAY.astype(np.float64), SOBEL_X.T, mode="valid")
    assert out.shape == (8, 10)
    assert np.allclose(out, expected(dx, dy), atol=1e-5)


def test_sobel_of_a_square_is_on_its_edges_and_uses_the_intensity(tmp_path):
    colour = np.stack([square(), square(), square() * 0.0])   # intensity 2/3 inside
    out, = outputs(tmp_path, "SobelEdgeDetector", {"INPUT": colour}, "OUTPUT")
    full = np.zeros((24, 24))
    full[1:-1, 1:-1] = out
    assert np.all(np.abs(full[~boundary()]) < 1e-6)
    # the middle of the left side: dx = (1 + 2 + 1) * 2/3
    assert full[12, 5] == pytest.approx(4 * 2 / 3, abs=1e-5)
    assert full[12, 6] == pytest.approx(4 * 2 / 3, abs=1e-5)


def test_sobel_sigma_blurs_first_and_ikaros3_keeps_the_size(tmp_path):
    blurred = ndimage.gaussian_filter(GRAY.astype(np.float64), 1.5, mode="reflect",
                                      truncate=4.0)
    out, = outputs(tmp_path, "SobelEdgeDetector", {"INPUT": GRAY}, "OUTPUT", sigma=1.5)
    assert np.allclose(out, np.hypot(correlate(blurred, SOBEL_X),
                                     correlate(blurred, SOBEL_X.T)), atol=1e-5)
    # Ikaros 3: sigma 1 by default, the output of the input's size (reflected border)
    blurred = ndimage.gaussian_filter(GRAY.astype(np.float64), 1.0, mode="reflect",
                                      truncate=4.0)
    body = (f'<module class="Constant" name="I" data="{literal(GRAY)}"/>'
            '<module class="SobelEdgeDetector" name="S"/>'
            '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    with load_body(tmp_path, body, dialect=3) as net:
        net.step()
        out = net.output("S.OUTPUT")
    dx = ndimage.correlate(blurred, SOBEL_X, mode="reflect")
    dy = ndimage.correlate(blurred, SOBEL_X.T, mode="reflect")
    assert out.shape == GRAY.shape
    assert np.allclose(out, np.hypot(dx, dy), atol=1e-5)


def test_prewitt_and_roberts_magnitudes(tmp_path):
    # Ikaros 2's kernels (its golden outputs), and Prewitt's as the option
    prewitt, = outputs(tmp_path, "PrewittEdgeDetector", {"INPUT": GRAY}, "OUTPUT")
    k1 = np.array([[-2, 0, 1], [-1, 0, 1], [0, 0, 1]])
    k2 = np.array([[0, -1, -1], [0, 0, 0], [0, 1, 1]])
    assert np.allclose(prewitt, np.hypot(correlate(GRAY, k1), correlate(GRAY, k2)),
                       atol=1e-5)
    prewitt, = outputs(tmp_path, "PrewittEdgeDetector", {"INPUT": GRAY}, "OUTPUT",
                       kernels="prewitt")
    kx = np.array([[-1, 0, 1]] * 3)
    assert np.allclose(prewitt, np.hypot(correlate(GRAY, kx), correlate(GRAY, kx.T)),
                       atol=1e-5)
    roberts, = outputs(tmp_path, "RobertsEdgeDetector", {"INPUT": GRAY}, "OUTPUT")
    d1 = GRAY[1:, 1:] - GRAY[:-1, :-1]
    d2 = GRAY[1:, :-1] - GRAY[:-1, 1:]
    assert roberts.shape == (9, 11)
    assert np.allclose(roberts, np.hypot(d1, d2), atol=1e-6)


def ikaros2_kernel():
    """dGx of Ikaros 2 (its golden outputs): -2x · exp(-(x² + y²)) on 5 x 5 offsets."""
    r = np.arange(-2, 3)
    x, y = r[None, :], r[:, None]
    return -2 * x * np.exp(-(x * x + y * y))


OFFSETS = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]


def suppressed(magnitude, dx, dy):
    """Ikaros 2's non-maximum suppression, pixel by pixel: the direction rounded to one of
    8 neighbours; an inner pixel stays when above the one behind and not below the one
    ahead; the border stays."""
    out = magnitude.copy()
    rows, cols = magnitude.shape
    for r in range(1, rows - 1):
        for c in range(1, cols - 1):
            k = int(np.rint(np.arctan2(dy[r, c], dx[r, c]) / (np.pi / 4))) % 8
            oc, orow = OFFSETS[k]
            m = magnitude[r, c]
            if not (m > magnitude[r - orow, c - oc] and m >= magnitude[r + orow, c + oc]):
                out[r, c] = 0
    return out


def test_gaussian_edge_detector_as_ikaros2(tmp_path):
    noise = np.random.default_rng(3).random((16, 16)).astype(np.float32)
    image = square(16, 4, 11) + noise * 0.1
    out, maxima, dx, dy, orientation, kx, ky = outputs(
        tmp_path, "GaussianEdgeDetector", {"INPUT": image}, "OUTPUT", "MAXIMA", "dx", "dy",
        "ORIENTATION", "dGx", "dGy")
    assert np.allclose(kx, ikaros2_kernel(), atol=1e-6) and np.allclose(ky, kx.T)
    gx, gy = correlate(image, ikaros2_kernel()), correlate(image, ikaros2_kernel().T)
    assert dx.shape == (12, 12)                          # 16 - 4: where the kernel fits
    assert np.allclose(dx, gx, atol=1e-5) and np.allclose(dy, gy, atol=1e-5)
    assert np.allclose(out, np.hypot(gx, gy), atol=1e-5)
    assert np.allclose(orientation, np.arctan2(gx, gy), atol=1e-5)
    assert np.allclose(maxima, suppressed(np.hypot(gx, gy), gx, gy), atol=1e-5)
    assert np.array_equal(maxima[0], out[0])             # the border is not suppressed
    assert np.count_nonzero(maxima[1:-1, 1:-1]) < np.count_nonzero(out[1:-1, 1:-1]) / 2


def test_canny_as_ikaros2(tmp_path):
    noise = np.random.default_rng(4).random((16, 16)).astype(np.float32)
    image = square(16, 4, 11) + noise * 0.1
    edges, maxima, out, dx, dy = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": image},
                                         "EDGES", "MAXIMA", "OUTPUT", "dx", "dy",
                                         T0=0.2, T1=0.5, T2=0.9)
    gx, gy = correlate(image, ikaros2_kernel()), correlate(image, ikaros2_kernel().T)
    magnitude = np.hypot(gx, gy)
    above = magnitude > 0.2
    assert np.allclose(edges, magnitude * above, atol=1e-5)
    k = np.rint(np.arctan2(gy, gx) / (np.pi / 4)).astype(int) % 8
    offsets = np.array(OFFSETS)[k]
    assert np.array_equal(dx, offsets[..., 0] * above)
    assert np.array_equal(dy, offsets[..., 1] * above)
    assert np.allclose(maxima, suppressed(magnitude * above, gx, gy), atol=1e-5)
    # edges: inner maxima above T2, and those above T1 connected to them
    inner = np.zeros_like(maxima, bool)
    inner[1:-1, 1:-1] = True
    labels, _ = ndimage.label((maxima > 0.5) & inner, np.ones((3, 3)))
    strong = np.unique(labels[(maxima > 0.9) & inner])
    expected = np.isin(labels, strong[strong > 0])
    assert expected.any() and np.array_equal(out, expected)
    assert not out[0].any() and not out[:, -1].any()


def test_canny_defaults_need_large_values(tmp_path):
    # a step of 1 gives the sum of dGx's positive half, about 1.43: below T0 = 100, and a
    # step of 255 (366) is above T0 and T1 but below T2 = 800
    image = square(16, 4, 11)
    step = ikaros2_kernel()[:, :2].sum()
    edges, out = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": image}, "EDGES", "OUTPUT")
    assert not edges.any() and not out.any()
    edges, out = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": image * 255}, "EDGES",
                         "OUTPUT")
    assert edges[5].max() == pytest.approx(255 * step, rel=1e-5) and not out.any()


def test_canny_as_ikaros3(tmp_path):
    image = square(32, 8, 24)
    body = (f'<module class="Constant" name="I" data="{literal(image)}"/>'
            '<module class="CannyEdgeDetector" name="C" {}/>'
            '<connection source="I.OUTPUT" target="C.INPUT" delay="0"/>')
    with load_body(tmp_path, body.format(""), dialect=3) as net:
        net.step()
        out, dx, kx = (net.output(f"C.{n}") for n in ("OUTPUT", "dx", "dGx"))
    assert out.shape == image.shape and set(np.unique(out)) == {0.0, 1.0}
    # the derivative of the image blurred with sigma 1: a ramp of slope 1 gives 1
    x = np.arange(-3, 4)
    g = np.exp(-(x[None, :] ** 2 + x[:, None] ** 2) / 2.0) * x[None, :]
    assert np.allclose(kx, g / (g * x[None, :]).sum(), atol=1e-6)
    assert np.allclose(dx, ndimage.correlate(image.astype(np.float64), kx, mode="reflect"),
                       atol=1e-5)
    assert np.all(out[~boundary(32, 8, 24)] == 0)
    assert np.all(out[8:24, 7:9].max(axis=1) == 1)       # the left side, every row
    # the step's gradient is about 0.4: a high threshold above it finds nothing
    with load_body(tmp_path, body.format('high_threshold="0.5"'), dialect=3) as net:
        net.step()
        assert not net.output("C.OUTPUT").any()


def raster_hysteresis(image, t1, t2, reach, iterations):
    """Ikaros 2's hysteresis, pixel by pixel: passes over the inner pixels in raster order;
    a strong or marked pixel marks the weak pixels of its square."""
    rows, cols = image.shape
    out = np.zeros((rows, cols))
    for _ in range(iterations):
        for r in range(reach, rows - reach):
            for c in range(reach, cols - reach):
                if image[r, c] > t2 or out[r, c]:
                    window = (slice(r - reach, r + reach + 1), slice(c - reach, c + reach + 1))
                    out[window][image[window] > t1] = 1
    return out


def test_hysteresis_follows_weak_edges_by_raster_passes(tmp_path):
    image = np.random.default_rng(5).random((9, 11)).astype(np.float32)
    for params in (dict(), dict(range=2, iterations=2, T1=0.2, T2=0.9)):
        out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": image}, "OUTPUT",
                       **params)
        t1, t2 = np.float32(params.get("T1", 0.3)), np.float32(params.get("T2", 0.6))
        assert np.array_equal(out, raster_hysteresis(image, t1, t2, params.get("range", 1),
                                                     params.get("iterations", 1)))
    # along the scan a weak edge is followed at once, against it one pixel per pass
    row = np.array([[0.1] * 7, [0.4, 0.4, 0.4, 0.7, 0.4, 0.4, 0.4], [0.1] * 7], np.float32)
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT")
    assert np.array_equal(out[1], [0, 0, 1, 1, 1, 1, 1])


def test_hysteresis_dilation_option(tmp_path):
    row = np.array([[0.7, 0.4, 0.4, 0.4, 0.1, 0.4, 0.4]], np.float32)
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT",
                   method="dilation")
    assert np.array_equal(out, [[1, 1, 0, 0, 0, 0, 0]])
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT",
                   iterations=5, method="dilation")
    assert np.array_equal(out, [[1, 1, 1, 1, 0, 0, 0]])
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT",
                   iterations=3, range=2, method="dilation")
    assert np.array_equal(out, [[1, 1, 1, 1, 0, 1, 0]])   # 2 further per iteration
    # with the original's scan a one-row image has no inner pixel: 0
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT")
    assert not out.any()


def test_zero_crossings(tmp_path):
    image = np.array([[1, -1, -2, 0, 3],
                      [2, 2, -1, 5, 4],
                      [-1, 1, 1, 1, 1],
                      [3, 3, -6, 2, -7]], np.float32)
    out, = outputs(tmp_path, "ZeroCrossings", {"INPUT": image}, "OUTPUT")
    rows, cols = image.shape
    expected = np.zeros((rows, cols), np.float32)
    for r in range(rows - 1):
        for c in range(cols - 1):
            here = image[r, c]
            if min(here * image[r + 1, c], here * image[r, c + 1],
                   here * image[r + 1, c + 1]) <= 0:
                expected[r, c] = 1
    assert np.array_equal(out, expected)
    assert out[1, 0] == 1                              # 2 above -1
    assert out[0, 2] == 1 and out[0, 3] == 1          # a product of 0 counts
    assert out[1, 3] == 0                              # 5: all three neighbours positive
    assert not out[-1].any() and not out[:, -1].any()  # last row and column stay 0


def test_zero_crossings_on_the_diagonal_only(tmp_path):
    image = np.array([[1, 2, 3], [2, -1, 4], [3, 4, 5]], np.float32)
    out, = outputs(tmp_path, "ZeroCrossings", {"INPUT": image}, "OUTPUT")
    # (0, 0): below 2, right 2, diagonal -1; (1, 1) is -1 with positive neighbours
    assert np.array_equal(out, [[1, 1, 0], [1, 1, 0], [0, 0, 0]])


def harris(dx, dy):
    """Ikaros 2's response: 4 x 4 sums over offsets -2..+1, 0 in a 2-pixel border."""
    rows, cols = dx.shape
    out = np.zeros((rows, cols))
    for r in range(2, rows - 2):
        for c in range(2, cols - 2):
            wx = dx[r - 2:r + 2, c - 2:c + 2].astype(np.float64)
            wy = dy[r - 2:r + 2, c - 2:c + 2].astype(np.float64)
            sxx, syy, sxy = (wx * wx).sum(), (wy * wy).sum(), (wx * wy).sum()
            out[r, c] = (sxx * syy - sxy * sxy) / (sxx + syy + 1e-5)
    return out


def test_harris_response_against_window_sums(tmp_path):
    dx, dy = RNG.standard_normal((2, 9, 10)).astype(np.float32)
    out, = outputs(tmp_path, "HarrisDetector", {"DX": dx, "DY": dy}, "OUTPUT")
    assert out.shape == (9, 10)
    assert np.allclose(out, harris(dx, dy), rtol=1e-4, atol=1e-5)
    assert not out[:2].any() and not out[-2:].any()
    assert not out[:, :2].any() and not out[:, -2:].any()


def test_harris_hand_checked_values(tmp_path):
    dx, dy = np.zeros((2, 6, 6), np.float32)
    dx[3, 3], dy[3, 3] = 1, 1        # alone in a window: Sxx Syy = Sxy², response 0
    dx[0, 0], dy[1, 1] = 2, 3        # in the windows of (2, 2) and (2, 3) only
    out, = outputs(tmp_path, "HarrisDetector", {"DX": dx, "DY": dy}, "OUTPUT")
    # (2, 2): rows 0..3, columns 0..3: Sxx = 4 + 1, Syy = 9 + 1, Sxy = 1
    assert out[2, 2] == pytest.approx((5 * 10 - 1) / (15 + 1e-5), rel=1e-6)
    # (2, 3): columns 1..4 hold (1, 1) and (3, 3): Sxx = 1, Syy = 10, Sxy = 1
    assert out[2, 3] == pytest.approx((10 - 1) / (11 + 1e-5), rel=1e-6)
    assert out[4, 4] == pytest.approx(0.0, abs=1e-6)   # rows and columns 2..5: (3, 3) only


def test_harris_is_largest_at_the_corners_of_a_square(tmp_path):
    image = square(20, 5, 15)
    body = (f'<module class="Constant" name="I" data="{literal(image)}"/>'
            '<module class="SobelEdgeDetector" name="DX" type="dx"/>'
            '<module class="SobelEdgeDetector" name="DY" type="dy"/>'
            '<module class="HarrisDetector" name="H"/>'
            '<connection source="I.OUTPUT" target="DX.INPUT" delay="0"/>'
            '<connection source="I.OUTPUT" target="DY.INPUT" delay="0"/>'
            '<connection source="DX.OUTPUT" target="H.DX" delay="0"/>'
            '<connection source="DY.OUTPUT" target="H.DY" delay="0"/>')
    with load_body(tmp_path, body) as net:
        net.step()
        response = net.output("H.OUTPUT")
    assert response.shape == (18, 18)                  # 20 - 2 (Sobel); Harris keeps it
    peaks = np.argwhere(response >= 0.9 * response.max()) + 1
    corners = np.array([[5, 5], [5, 14], [14, 5], [14, 14]])
    distance = np.abs(peaks[:, None, :] - corners[None]).max(axis=2).min(axis=1)
    assert distance.max() <= 1                         # every peak at a corner
    assert response[8, 8] == 0 and response.min() >= -1e-3   # flat inside; no negatives


def test_fast_finds_the_corners_of_a_square(tmp_path):
    image = square(32, 8, 24)
    out, points, count = outputs(tmp_path, "FASTDetector", {"INPUT": image}, "OUTPUT",
                                 "POINTS", "POINT_COUNT", max_points=10)
    n = int(count[0])
    assert n == 4 and points.shape == (10, 2) and np.all(points[n:] == 0)
    corners = np.array([[8, 8], [23, 8], [8, 23], [23, 23]])
    found = points[:n]
    assert np.abs(found[:, None, :] - corners[None]).max(axis=2).min(axis=1).max() <= 1
    assert out.sum() == 4 and np.all(out[found[:, 1].astype(int), found[:, 0].astype(int)])
    faint, = outputs(tmp_path, "FASTDetector", {"INPUT": image * 0.1}, "POINT_COUNT")
    assert faint[0] == 0                               # 26 levels: below the threshold 40


def circle_edges(cx, cy, radius, n=180, outward=True):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    angle = t if outward else t + np.pi
    return np.stack([cx + radius * np.cos(t), cy + radius * np.sin(t), angle,
                     np.ones(n)], axis=1)


def test_circle_detector_finds_centre_and_diameter(tmp_path):
    edges = np.zeros((300, 4))
    edges[:180] = circle_edges(60.3, 45.6, 27.0, outward=False)
    edges[180:200] = RNG.uniform(0, 120, (20, 4))    # clutter
    pos, diameter, histdx = outputs(tmp_path, "CircleDetector",
                                    {"EDGE_LIST": edges, "EDGE_LIST_SIZE": [200]},
                                    "POSITION", "DIAMETER", "HISTDX")
    assert pos[0] == pytest.approx(60.3, abs=0.5) and pos[1] == pytest.approx(45.6, abs=0.5)
    assert diameter[0] == pytest.approx(54.0, abs=1.0)
    assert pos[2] == pytest.approx(0.9, abs=0.05)
    assert histdx.sum() == 200


def test_circle_from_an_image_through_the_edge_modules(tmp_path):
    rows, cols = np.mgrid[0:80, 0:90]
    # a soft disc: the 5 x 5 kernels of Ikaros 2's GaussianEdgeDetector give good
    # orientations on it
    disc = ndimage.gaussian_filter((np.hypot(cols - 47, rows - 38) <= 22).astype(float), 2)
    body = (f'<module class="Constant" name="I" data="{literal(disc)}"/>'
            '<module class="GaussianEdgeDetector" name="E"/>'
            '<module class="EdgeSegmentation" name="S" threshold="0.3" max_edges="2000"/>'
            '<module class="CircleDetector" name="C"/>'
            '<connection source="I.OUTPUT" target="E.INPUT" delay="0"/>'
            '<connection source="E.MAXIMA" target="S.INPUT" delay="0"/>'
            '<connection source="E.dx" target="S.DX" delay="0"/>'
            '<connection source="E.dy" target="S.DY" delay="0"/>'
            '<connection source="S.EDGE_LIST" target="C.EDGE_LIST" delay="0"/>'
            '<connection source="S.EDGE_LIST_SIZE" target="C.EDGE_LIST_SIZE" delay="0"/>')
    with load_body(tmp_path, body) as net:
        net.step()
        n = int(net.output("S.EDGE_LIST_SIZE")[0])
        position, diameter = net.output("C.POSITION"), net.output("C.DIAMETER")
    assert n > 100
    # in the detector's output, 2 rows and columns in from the image's
    assert position[0] == pytest.approx(45, abs=1) and position[1] == pytest.approx(36, abs=1)
    assert diameter[0] == pytest.approx(44, abs=2)


def test_edge_segmentation_lists_elements_on_a_grid(tmp_path):
    edges = np.zeros((6, 8), np.float32)
    edges[2, 3], edges[4, 6], edges[1, 1], edges[4, 2] = 2.0, 1.0, 0.1, 0.8
    dx = np.ones((6, 8), np.float32)
    dy = np.zeros((6, 8), np.float32)
    dy[4, 6] = 1.0
    out, table, segments, size = outputs(
        tmp_path, "EdgeSegmentation", {"INPUT": edges, "DX": dx, "DY": dy}, "OUTPUT",
        "EDGE_LIST", "EDGE_ELEMENTS", "EDGE_LIST_SIZE", max_edges=5, grid=2)
    # on the grid (even rows and columns) and above 0.1 after normalising by 2
    assert size[0] == 2
    assert np.allclose(table[:2], [[2, 4, 0, 0.4], [6, 4, np.pi / 4, 0.5]])
    assert np.all(table[2:] == 0)
    assert np.allclose(segments[0], [2, 3, 2, 5])      # across a gradient to the right
    s = np.sqrt(0.5)
    assert np.allclose(segments[1], [6 + s, 4 - s, 6 - s, 4 + s])
    assert np.all(segments[2:] == 0)
    expected = np.zeros((6, 8))
    expected[4, 6] = 0.5
    expected[4, 2] = 0.4
    assert np.allclose(out, expected)


def test_inputs_of_different_sizes_are_a_model_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="INPUT, DX and DY must have the same size"):
        run(tmp_path, "EdgeSegmentation", {"INPUT": GRAY, "DX": GRAY, "DY": GRAY[1:]})
    with pytest.raises(ikaros.ModelError, match="INPUT must be a gray image"):
        run(tmp_path, "ZeroCrossings", {"INPUT": np.zeros((3, 4, 4))})
