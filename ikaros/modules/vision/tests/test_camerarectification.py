"""Tests of the CameraRectification module (Ikaros 3, MODULES-V3 §20)."""
import numpy as np

from ikaros.testing import load_body as load, matrix_text


def _run(tmp_path, image, K, distortion, attrs=""):
    data = str(np.asarray(image).tolist()) if np.ndim(image) == 3 else matrix_text(image)
    net = load(tmp_path, f'<module class="Constant" name="I" data="{data}"/>'
                         f'<module class="Constant" name="K" data="{matrix_text(K)}"/>'
                         f'<module class="Constant" name="D" data="{distortion}"/>'
                         f'<module class="CameraRectification" name="R" {attrs}/>'
                         '<connection source="I.OUTPUT" target="R.INPUT" delay="0"/>'
                         '<connection source="K.OUTPUT" target="R.CAMERA_MATRIX" delay="0"/>'
                         '<connection source="D.OUTPUT" target="R.DISTORTION" delay="0"/>')
    try:
        net.step()
        return net.output("R.OUTPUT").copy()
    finally:
        net.close()


def test_no_distortion_is_the_identity(tmp_path):
    image = np.arange(20, dtype=float).reshape(4, 5)
    K = [[2, 0, 2], [0, 2, 1.5], [0, 0, 1]]
    assert np.allclose(_run(tmp_path, image, K, "0 0 0 0"), image)


def test_radial_distortion_samples_bilinearly_with_a_border(tmp_path):
    rows, cols = 5, 7
    image = np.add.outer(np.arange(rows) * 10.0, np.arange(cols))   # value = 10 y + x
    fx, fy, cx, cy, k1 = 3.0, 2.0, 3.0, 2.0, 0.05
    out = _run(tmp_path, image, [[fx, 0, cx], [0, fy, cy], [0, 0, 1]], f"{k1} 0 0 0",
               'border_value="-1"')
    y, x = np.mgrid[0:rows, 0:cols].astype(float)
    xn, yn = (x - cx) / fx, (y - cy) / fy
    radial = 1 + k1 * (xn ** 2 + yn ** 2)
    sx, sy = fx * xn * radial + cx, fy * yn * radial + cy
    inside = (sx >= 0) & (sx <= cols - 1) & (sy >= 0) & (sy <= rows - 1)
    # the image is linear in x and y, so bilinear sampling gives 10 sy + sx exactly
    expected = np.where(inside, 10 * sy + sx, -1)
    assert (~inside).any() and inside.any()
    assert np.allclose(out, expected, atol=1e-4)


def test_a_colour_image_is_rectified_plane_by_plane(tmp_path):
    gray = np.arange(12, dtype=float).reshape(3, 4)
    colour = np.stack([gray, 2 * gray, -gray])
    K = [[4, 0, 1.5], [0, 4, 1], [0, 0, 1]]
    out = _run(tmp_path, colour, K, "0.1 0 0.01 0")
    one = _run(tmp_path, gray, K, "0.1 0 0.01 0")
    assert out.shape == (3, 3, 4)
    assert np.allclose(out, [one, 2 * one, -one], atol=1e-5)
