"""CameraRectification against the Ikaros 3 description (MODULES-V3 §20), computed here
pixel by pixel in plain Python."""
import math

import numpy as np
import pytest

import ikaros
from vision_models import outputs, run

RNG = np.random.default_rng(21)
K = [[5.0, 0, 3.5], [0, 6.0, 2.5], [0, 0, 1]]


def undistort(image, k, d, border=0.0):
    """The description's map and bilinear sampling, one pixel at a time."""
    d = list(d) + [0.0] * (14 - len(d))
    k1, k2, p1, p2, k3, k4, k5, k6, s1, s2, s3, s4 = d[:12]
    fx, fy, cx, cy = k[0][0], k[1][1], k[0][2], k[1][2]
    rows, cols = image.shape
    out = np.zeros((rows, cols))
    for y in range(rows):
        for x in range(cols):
            xn, yn = (x - cx) / fx, (y - cy) / fy
            r2 = xn * xn + yn * yn
            num = 1 + k1 * r2 + k2 * r2 ** 2 + k3 * r2 ** 3
            den = 1 + k4 * r2 + k5 * r2 ** 2 + k6 * r2 ** 3
            radial = num / den if den != 0 else num
            xd = xn * radial + 2 * p1 * xn * yn + p2 * (r2 + 2 * xn * xn) + s1 * r2 + s2 * r2 ** 2
            yd = yn * radial + p1 * (r2 + 2 * yn * yn) + 2 * p2 * xn * yn + s3 * r2 + s4 * r2 ** 2
            sx, sy = fx * xd + cx, fy * yd + cy
            if not (0 <= sx <= cols - 1 and 0 <= sy <= rows - 1):
                out[y, x] = border
                continue
            x0, y0 = math.trunc(sx), math.trunc(sy)
            x1, y1 = min(x0 + 1, cols - 1), min(y0 + 1, rows - 1)
            ax, ay = sx - x0, sy - y0
            top = image[y0, x0] * (1 - ax) + image[y0, x1] * ax
            bottom = image[y1, x0] * (1 - ax) + image[y1, x1] * ax
            out[y, x] = top * (1 - ay) + bottom * ay
    return out


def test_no_distortion_keeps_the_image(tmp_path):
    image = RNG.random((3, 5, 7)).astype(np.float32)
    out, = outputs(tmp_path, "CameraRectification", {"INPUT": image, "CAMERA_MATRIX": K,
                                                    "DISTORTION": [0, 0, 0, 0]}, "OUTPUT")
    assert np.allclose(out, image, atol=1e-6)


@pytest.mark.parametrize("d", [[0.3, -0.1, 0.02, -0.01],
                               [0.6, 0.05, 0, 0, 0.01, 0.1, 0.02, 0.003],
                               [0.1, 0, 0, 0, 0, 0, 0, 0, 0.01, -0.02, 0.03, 0.01]])
def test_distortion_model_and_border(tmp_path, d):
    image = RNG.random((6, 8)).astype(np.float32)
    out, = outputs(tmp_path, "CameraRectification", {"INPUT": image, "CAMERA_MATRIX": K,
                                                    "DISTORTION": d}, "OUTPUT",
                   border_value=-1)
    expected = undistort(image.astype(np.float64), K, d, border=-1)
    assert (expected == -1).any() and (expected != -1).any()
    assert np.allclose(out, expected, atol=1e-4)


def test_zero_focal_length_warns_and_leaves_the_output(tmp_path):
    k = [[0.0, 0, 3.5], [0, 6.0, 2.5], [0, 0, 1]]
    with run(tmp_path, "CameraRectification", {"INPUT": np.ones((4, 4)), "CAMERA_MATRIX": k,
                                               "DISTORTION": [0.1, 0, 0, 0]}, ticks=2) as net:
        assert not net.output("M.OUTPUT").any()
        assert sum("fx or fy" in m for *_, m in net.log) == 1


def test_tilt_terms_are_ignored_with_a_warning(tmp_path):
    image = RNG.random((6, 8)).astype(np.float32)
    d = [0.1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.2, 0.1]
    with run(tmp_path, "CameraRectification", {"INPUT": image, "CAMERA_MATRIX": K,
                                               "DISTORTION": d}) as net:
        assert np.allclose(net.output("M.OUTPUT"), undistort(image, K, d[:12]), atol=1e-4)
        assert any("tilt" in m for *_, m in net.log)


def test_bad_inputs_are_model_errors(tmp_path):
    with pytest.raises(ikaros.ModelError, match="at least 4"):
        run(tmp_path, "CameraRectification", {"INPUT": np.ones((4, 4)), "CAMERA_MATRIX": K,
                                              "DISTORTION": [0.1, 0, 0]})
    with pytest.raises(ikaros.ModelError, match="3 x 3"):
        run(tmp_path, "CameraRectification", {"INPUT": np.ones((4, 4)),
                                              "CAMERA_MATRIX": [[1, 0], [0, 1]],
                                              "DISTORTION": [0, 0, 0, 0]})
