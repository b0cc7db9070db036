"""Tests of ColorTransform, ColorClassifier and ColorMatch against colour-space values
computed here from the CIE and sRGB definitions."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body
from vision_models import literal, outputs, run

RNG = np.random.default_rng(5)

M = np.array([[0.412453, 0.357580, 0.180423],          # linear sRGB -> XYZ (D65)
              [0.212671, 0.715160, 0.072169],
              [0.019334, 0.119193, 0.950227]])
WHITE = M.sum(axis=1)


def lab(rgb):
    """CIE L*a*b* of sRGB values 0..1 (gamma-expanded), from the definitions."""
    rgb = np.asarray(rgb, float)
    linear = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    xyz = (M @ linear.reshape(3, -1)).reshape(rgb.shape) / WHITE.reshape((3,) + (1,) * (
        rgb.ndim - 1))
    f = np.where(xyz > (6 / 29) ** 3, np.cbrt(xyz), xyz / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.stack([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def pixels(*colours):
    """A (3, 1, n) colour image of the given (r, g, b) pixels."""
    return np.asarray(colours, np.float32).T[:, None, :]


def test_rgb_to_lab_known_values(tmp_path):
    image = pixels((1, 0, 0), (0.5, 0.5, 0.5), (0.2, 0.6, 0.9), (1, 1, 1))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT")
    assert np.allclose(out[:, 0, 0], (53.24, 80.09, 67.20), atol=0.05)  # the textbook red
    assert np.allclose(out, lab(image), atol=0.2)      # OpenCV interpolates in tables
    assert np.allclose(out[:, 0, 3], (100, 0, 0), atol=0.05)


def test_rgb_to_xyz_is_linear_and_planes_are_outputs_too(tmp_path):
    image = RNG.random((3, 4, 5)).astype(np.float32)
    planes = {f"INPUT{i}": image[i] for i in range(3)}
    out, x, y, z = outputs(tmp_path, "ColorTransform", planes, "OUTPUT", "OUTPUT0", "OUTPUT1",
                           "OUTPUT2", transform="RGB->XYZ", scale=2)
    expected = 2 * np.einsum("ij,jrc->irc", M, image)
    assert np.allclose(out, expected, atol=1e-4)
    assert np.array_equal(x, out[0]) and np.array_equal(y, out[1]) and np.array_equal(z, out[2])


def test_lab_and_xyz_round_trips(tmp_path):
    image = RNG.uniform(0.05, 0.95, (3, 3, 4)).astype(np.float32)
    body = (f'<module class="Constant" name="C" data="{literal(image)}"/>'
            '<module class="ColorTransform" name="A" transform="RGB->Lab"/>'
            '<module class="ColorTransform" name="B" transform="Lab->RGB"/>'
            '<module class="ColorTransform" name="X" transform="RGB->XYZ"/>'
            '<module class="ColorTransform" name="Y" transform="XYZ->RGB"/>'
            '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>'
            '<connection source="A.OUTPUT" target="B.INPUT" delay="0"/>'
            '<connection source="C.OUTPUT" target="X.INPUT" delay="0"/>'
            '<connection source="X.OUTPUT" target="Y.INPUT" delay="0"/>')
    with load_body(tmp_path, body) as net:
        net.step()
        assert np.allclose(net.output("B.OUTPUT"), image, atol=5e-3)
        assert np.allclose(net.output("Y.OUTPUT"), image, atol=1e-4)


def test_rgb_to_rgi(tmp_path):
    image = pixels((0.6, 0.3, 0.3), (0, 0, 0), (0.1, 0.2, 0.7))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT", transform="RGB->rgI")
    total = image.sum(axis=0)
    assert np.allclose(out[0, 0], [0.5, 0, 0.1], atol=1e-6)
    assert np.allclose(out[1, 0], [0.25, 0, 0.2], atol=1e-6)
    assert np.allclose(out[2], total / 3, atol=1e-6)


def test_partial_plane_inputs_are_a_model_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="connect either INPUT"):
        run(tmp_path, "ColorTransform", {"INPUT0": np.zeros((2, 2)), "INPUT": pixels((1, 1, 1))})


def classify(tmp_path, image, **params):
    """rgI through ColorTransform, then ColorClassifier."""
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = (f'<module class="Constant" name="C" data="{literal(image)}"/>'
            '<module class="ColorTransform" name="T" transform="RGB->rgI"/>'
            f'<module class="ColorClassifier" name="K" {attrs}/>'
            '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>'
            '<connection source="T.OUTPUT0" target="K.R" delay="0"/>'
            '<connection source="T.OUTPUT1" target="K.G" delay="0"/>'
            '<connection source="T.OUTPUT2" target="K.I" delay="0"/>')
    with load_body(tmp_path, body) as net:
        net.step()
        return [net.output(f"K.{n}") for n in ("OUTPUT", "COLORSPACE_R", "COLORSPACE_G",
                                                 "COLORSPACE_B")]


def test_classifier_selects_a_hue_sector(tmp_path):
    # blue-ish (hue 225 exactly: r = g), pale blue, red, gray, a blue at hue 225 + 12
    t = np.radians(237)
    tilted = (1 / 3 + 0.3 * np.cos(t), 1 / 3 + 0.3 * np.sin(t))
    colours = [(0.1, 0.1, 0.5), (0.5, 0.5, 0.6), (0.8, 0.1, 0.1), (0.4, 0.4, 0.4),
               (tilted[0], tilted[1], 1 - sum(tilted))]
    image = pixels(*colours)
    out, *_ = classify(tmp_path, image)
    # saturation of (0.1, 0.1, 0.5): r = g = 1/7, distance from white sqrt(2) * (1/3 - 1/7)
    assert np.array_equal(out[0], [1, 0, 0, 0, 0])
    out, *_ = classify(tmp_path, image, width=30)
    assert np.array_equal(out[0], [1, 0, 0, 0, 1])
    out, *_ = classify(tmp_path, image, color=333.4, width=10, saturation_max=0.75)
    assert np.array_equal(out[0], [0, 0, 1, 0, 0])


def test_classifier_compensation_removes_a_colour_cast(tmp_path):
    cast = np.array([1.0, 1.0, 1.4])[:, None, None]
    grays = pixels((0.5, 0.5, 0.5), (0.3, 0.3, 0.3), (0.6, 0.6, 0.6))
    out, *_ = classify(tmp_path, grays * cast, saturation_min=0.02)
    assert out.all()                                    # the cast looks blue
    out, *_ = classify(tmp_path, grays * cast, saturation_min=0.02, compensation="yes")
    assert not out.any()


def test_classifier_diagnostic_plane(tmp_path):
    out, red, green, blue = classify(tmp_path, pixels((0.0, 0.0, 1.0), (1.0, 0.0, 0.0)),
                                     saturation_max=0.75)
    assert red.shape == (256, 256)
    assert (red[255, 0], green[255, 0], blue[255, 0]) == (1, 1, 1)   # blue pixel at r=g=0
    assert (red[255, 255], green[255, 255], blue[255, 255]) == (1, 1, 1)   # red at r=1
    # the point r = g = 0.2 is in the blue sector: full brightness; r = 0.6, g = 0.3 not
    r, g = 51, 204
    assert blue[g, r] == pytest.approx(0.6, abs=1e-6)
    assert red[255 - 77, 153] == pytest.approx(0.5 * 153 / 255, abs=1e-6)
    assert red[0, 255] == 0 and green[0, 255] == 0     # r + g > 1 is outside


def test_color_match_similarity(tmp_path):
    image = RNG.uniform(0, 100, (3, 4, 6)).astype(np.float32)
    out, = outputs(tmp_path, "ColorMatch", {"INPUT": image}, "OUTPUT", target0=50,
                   target1=20, target2=70, sigma=30, gain=2, threshold=0.5)
    d2 = ((image - np.array([50, 20, 70])[:, None, None]) ** 2).sum(axis=0)
    expected = 2 * np.exp(-d2 / (2 * 30 ** 2))
    expected[expected < 0.5] = 0
    assert np.allclose(out, expected, atol=1e-5)


def test_color_match_learns_the_colour_at_the_focus(tmp_path):
    image = np.zeros((3, 4, 4), np.float32)
    image[:, 1, 3] = (10, 20, 30)                      # x = 0.9, y = 0.3 is in this pixel
    inputs = {"INPUT0": image[0], "INPUT1": image[1], "INPUT2": image[2],
              "FOCUS": [0.9, 0.3], "REINFORCEMENT": [0.5]}
    with run(tmp_path, "ColorMatch", inputs, ticks=0, alpha=0.2, sigma=10) as net:
        net.step()
        out = net.output("M.OUTPUT")
        prototype = 0.1 * np.array([10, 20, 30])       # alpha * reinforcement = 0.1
        d2 = ((image - prototype[:, None, None]) ** 2).sum(axis=0)
        assert np.allclose(out, np.exp(-d2 / 200), atol=1e-6)
        net.run(ticks=200)
        assert net.output("M.OUTPUT")[1, 3] == pytest.approx(1.0, abs=1e-3)
