"""ImageMatching finds the centre of one image in a moved copy of it, with the correlation
profile written out in NumPy; PointsToSalience gives a Gaussian bump at each point."""
import numpy as np
import pytest

from ikaros.errors import ModelError

from textures import moved, texture
from vision_models import run

cv2 = pytest.importorskip("cv2")


def ncc(a, b):
    """Normalised cross-correlation of two equal patches (TM_CCOEFF_NORMED's formula)."""
    a, b = a - a.mean(), b - b.mean()
    return float((a * b).sum() / np.sqrt((a * a).sum() * (b * b).sum()))


@pytest.mark.parametrize("dx, dy", [(7, -3), (-12, 5), (0, 0)])
def test_finds_the_centre_of_left_moved_in_right(tmp_path, dx, dy):
    left = texture(rows=60, cols=80, seed=2)
    right = moved(left, dx, dy)
    with run(tmp_path, "ImageMatching", {"LEFT": left, "RIGHT": right},
             focus_size="0.04", search_size="0.5") as net:
        out, focus, target = (net.output(f"M.{n}") for n in ("OUTPUT", "FOCUS", "TARGET"))
        profile = net.output("M.PROFILE")
    assert np.allclose(out, [dx / 80, dy / 60], atol=1e-6)
    # the focus: side sqrt(0.04 * 4800) = 13.9 -> 14 pixels, top-left (23, 33)
    side, top, left_col = 14, 23, 33
    x0, y0, x1, y1 = left_col / 80, top / 60, (left_col + side) / 80, (top + side) / 60
    assert np.allclose(focus, [[x0, y0, x1, y0], [x1, y0, x1, y1], [x1, y1, x0, y1],
                               [x0, y1, x0, y0]], atol=1e-6)
    assert np.allclose(target, focus + [dx / 80, dy / 60] * 2, atol=1e-6)
    # the profile: the search square has side sqrt(0.5 * 4800) = 49 pixels, top-left (5, 15)
    # squares centred on columns 15 + 7 = 22 to 22 + (49 - 14) = 57 lie inside it
    patch = left[top:top + side, left_col:left_col + side]
    for c in (22, 40, 57):
        start = c - side // 2
        best = max(ncc(patch, right[r:r + side, start:start + side])
                   for r in range(5, 5 + 49 - side + 1))
        assert profile[c] == pytest.approx(best, abs=1e-4)
    assert not profile[:22].any() and not profile[58:].any() and profile[22:58].all()
    assert profile.shape == (80,)


def test_left_and_right_of_different_sizes_are_refused(tmp_path):
    with pytest.raises(ModelError, match="same size"):
        run(tmp_path, "ImageMatching", {"LEFT": np.zeros((10, 12)), "RIGHT": np.zeros((10,
                                                                                     14))})


def bumps(points, sigmas, rows, cols):
    """The salience map written out element by element."""
    out = np.zeros((rows, cols))
    for r in range(rows):
        for c in range(cols):
            u, v = (c + 0.5) / cols, (r + 0.5) / rows
            out[r, c] = sum(np.exp(-((u - x) ** 2 + (v - y) ** 2) / (2 * s * s))
                            for (x, y), s in zip(points, sigmas))
    return out


def test_salience_is_a_gaussian_bump_at_each_point(tmp_path):
    points = np.array([[0.25, 0.5], [0.8, 0.1], [0, 0]])         # the last row is unused
    with run(tmp_path, "PointsToSalience", {"POINTS": points}, size_x="12", size_y="8",
             standard_deviation="0.1") as net:
        out = net.output("M.OUTPUT")
    assert out.shape == (8, 12)
    assert np.allclose(out, bumps(points[:2], [0.1, 0.1], 8, 12), atol=1e-6)


def test_salience_widths_scale_the_bumps(tmp_path):
    points = np.array([[0.25, 0.5], [0.8, 0.1]])
    with run(tmp_path, "PointsToSalience", {"POINTS": points, "WIDTHS": [0.5, 2.0]},
             size_x="10", size_y="10") as net:
        out = net.output("M.OUTPUT")
    assert np.allclose(out, bumps(points, [0.1, 0.4], 10, 10), atol=1e-6)


def test_salience_points_must_be_pairs(tmp_path):
    with pytest.raises(ModelError, match=r"POINTS must have rows \(x, y\)"):
        run(tmp_path, "PointsToSalience", {"POINTS": np.zeros((2, 3))})
