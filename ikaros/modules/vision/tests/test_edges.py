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
    out, = outputs(tmp_path, "SobelEdgeDetector", {"INPUT": GRAY}, "OUTPUT", type=kind)
    dx, dy = correlate(GRAY, SOBEL_X), correlate(GRAY, SOBEL_X.T)
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


def test_prewitt_and_roberts_magnitudes(tmp_path):
    prewitt, = outputs(tmp_path, "PrewittEdgeDetector", {"INPUT": GRAY}, "OUTPUT")
    kx = np.array([[-1, 0, 1]] * 3)
    assert np.allclose(prewitt, np.hypot(correlate(GRAY, kx), correlate(GRAY, kx.T)),
                       atol=1e-5)
    roberts, = outputs(tmp_path, "RobertsEdgeDetector", {"INPUT": GRAY}, "OUTPUT")
    d1 = GRAY[1:, 1:] - GRAY[:-1, :-1]
    d2 = GRAY[1:, :-1] - GRAY[:-1, 1:]
    assert roberts.shape == (9, 11)
    assert np.allclose(roberts, np.hypot(d1, d2), atol=1e-6)


def test_gaussian_edge_detector_on_a_ramp_and_a_square(tmp_path):
    ramp = np.tile(np.arange(16, dtype=np.float32) * 0.05, (16, 1))
    dx, dy, orientation, kx = outputs(tmp_path, "GaussianEdgeDetector", {"INPUT": ramp},
                                      "dx", "dy", "ORIENTATION", "dGx", scale=1.5)
    assert kx.shape == (11, 11)
    assert np.allclose(dx[5:-5, 5:-5], 0.05, atol=1e-6)       # slope 0.05 per pixel
    assert np.allclose(dy, 0.0, atol=1e-6)
    assert np.allclose(orientation[5:-5, 5:-5], 0.0, atol=1e-4)
    image = square()
    out, maxima, dx, kx, ky = outputs(tmp_path, "GaussianEdgeDetector", {"INPUT": image},
                                      "OUTPUT", "MAXIMA", "dx", "dGx", "dGy")
    assert np.allclose(ky, kx.T)
    assert np.allclose(dx[3:-3, 3:-3], correlate(image, kx), atol=1e-5)
    # maxima lie on the boundary, and every side of the square has them
    assert np.all(maxima[~boundary()] == 0)
    assert maxima[12, 5:7].max() > 0 and maxima[12, 17:19].max() > 0
    assert maxima[5:7, 12].max() > 0 and maxima[17:19, 12].max() > 0
    assert np.count_nonzero(maxima[12]) == 2           # one pixel thick across each side


def test_canny_finds_the_square(tmp_path):
    image = square(32, 8, 24)
    edges, dx, out, maxima, kx = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": image},
                                         "EDGES", "dx", "OUTPUT", "MAXIMA", "dGx")
    assert kx.shape == (7, 7) and kx[kx > 0].sum() == pytest.approx(1020, rel=1e-5)
    assert np.allclose(dx[3:-3, 3:-3], correlate(image, kx), rtol=1e-4, atol=1e-2)
    assert dx[16, 7] == pytest.approx(1020, rel=1e-5) and dx[16, 8] == dx[16, 7]
    assert set(np.unique(edges)) == {0.0, 1.0}
    near = boundary(32, 8, 24)
    assert np.all(edges[~near] == 0)
    assert np.all(edges[8:24, 7:9].max(axis=1) == 1)   # the left side, every row
    assert np.all(maxima[maxima > 0] > 100) and np.all(maxima <= out)


def test_canny_thresholds_drop_weak_edges(tmp_path):
    faint = square(32, 8, 24, value=0.5)               # magnitude 510 beside the edge
    edges, = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": faint}, "EDGES")
    assert not edges.any()
    edges, = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": faint}, "EDGES", T2=500)
    assert edges.any()
    # a faint square touching a strong one is followed from it
    image = square(32, 8, 24, value=0.5)
    image[8:24, 8:12] = 1.0
    edges, = outputs(tmp_path, "CannyEdgeDetector", {"INPUT": image}, "EDGES", scale=2)
    assert np.all(edges[9:23, 23:25].max(axis=1) == 1)   # the faint right side


def test_hysteresis_follows_weak_edges_from_strong_ones(tmp_path):
    row = np.array([[0.7, 0.4, 0.4, 0.4, 0.1, 0.4, 0.4]], np.float32)
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT")
    assert np.array_equal(out, [[1, 1, 0, 0, 0, 0, 0]])
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT", iterations=5)
    assert np.array_equal(out, [[1, 1, 1, 1, 0, 0, 0]])
    out, = outputs(tmp_path, "HysteresisThresholding", {"INPUT": row}, "OUTPUT", iterations=3,
                   range=2)
    assert np.array_equal(out, [[1, 1, 1, 1, 0, 1, 0]])   # 2 further per iteration


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
    disc = (np.hypot(cols - 47, rows - 38) <= 22).astype(np.float32)
    body = (f'<module class="Constant" name="I" data="{literal(disc)}"/>'
            '<module class="GaussianEdgeDetector" name="E" scale="1.5"/>'
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
    assert position[0] == pytest.approx(47, abs=1) and position[1] == pytest.approx(38, abs=1)
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
