"""Tests of ColorTransform, ColorClassifier and ColorMatch against colour-space values
computed here from the CIE and sRGB definitions."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body
from vision_models import literal, outputs, run

RNG = np.random.default_rng(5)

M = np.array([[0.412453, 0.357580, 0.180423],          # linear BT.709 RGB -> XYZ (D65)
              [0.212671, 0.715160, 0.072169],
              [0.019334, 0.119193, 0.950227]])
WHITE = np.array([0.950456, 1.0, 1.088754])


def lab(rgb, srgb=False):
    """CIE L*a*b* of RGB values 0..1, from the definitions: linear RGB as the original
    takes it, or sRGB-encoded values (gamma-expanded first)."""
    rgb = np.asarray(rgb, float)
    if srgb:
        rgb = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    xyz = np.einsum("ij,j...->i...", M, rgb) / WHITE.reshape((3,) + (1,) * (rgb.ndim - 1))
    f = np.where(xyz > (6 / 29) ** 3, np.cbrt(xyz), xyz / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.stack([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def pixels(*colours):
    """A (3, 1, n) colour image of the given (r, g, b) pixels."""
    return np.asarray(colours, np.float32).T[:, None, :]


def test_rgb_to_lab_takes_rgb_as_linear(tmp_path):
    image = pixels((0.5, 0.5, 0.5), (1, 1, 1), (0.2, 0.6, 0.9), (0.004, 0.002, 0.001))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT")
    # Y of a grey of 0.5 is 0.5: L = 116 * 0.5^(1/3) - 16 = 76.07 (not sRGB's 53.39)
    assert out[0, 0, 0] == pytest.approx(116 * 0.5 ** (1 / 3) - 16, abs=1e-3)
    assert out[0, 0, 0] == pytest.approx(76.07, abs=0.005)
    assert np.allclose(out[:, 0, 1], (100, 0, 0), atol=1e-3)
    assert np.allclose(out, lab(image), atol=2e-3)     # also the line below Y = 0.008856


def test_rgb_to_lab_scale_divides_the_inputs(tmp_path):
    image = pixels((230, 76, 25), (128, 128, 128))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT", scale=255)
    assert np.allclose(out, lab(image / 255), atol=2e-3)


def test_gamma_srgb_is_the_srgb_conversion(tmp_path):
    image = pixels((1, 0, 0), (0.5, 0.5, 0.5), (0.2, 0.6, 0.9))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT", gamma="srgb")
    assert np.allclose(out[:, 0, 0], (53.24, 80.09, 67.20), atol=0.05)  # the textbook red
    assert out[0, 0, 1] == pytest.approx(53.39, abs=0.01)
    assert np.allclose(out, lab(image, srgb=True), atol=2e-3)
    back, = outputs(tmp_path, "ColorTransform", {"INPUT": out}, "OUTPUT", gamma="srgb",
                    transform="Lab->RGB", ignore_transform="no")
    assert np.allclose(back, image, atol=1e-4)


def test_lab_to_rgb_is_the_inverse_clamped_to_0_1(tmp_path):
    image = RNG.uniform(0.05, 0.95, (3, 1, 4))
    colours = np.concatenate([lab(image), lab(pixels((1.5, 0.5, -0.2)))], axis=2)
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": colours}, "OUTPUT",
                   transform="Lab->RGB", ignore_transform="no")
    assert np.allclose(out[:, :, :4], image, atol=1e-4)  # no gamma compression
    assert np.allclose(out[:, 0, 4], (1, 0.5, 0), atol=1e-4)


def test_rgb_to_xyz_is_linear_and_planes_are_outputs_too(tmp_path):
    image = RNG.random((3, 4, 5)).astype(np.float32)
    planes = {f"INPUT{i}": image[i] for i in range(3)}
    out, x, y, z = outputs(tmp_path, "ColorTransform", planes, "OUTPUT", "OUTPUT0", "OUTPUT1",
                           "OUTPUT2", transform="RGB->XYZ", scale=0.5,
                           ignore_transform="no")
    expected = 2 * np.einsum("ij,jrc->irc", M, image)
    assert np.allclose(out, expected, atol=1e-4)
    assert np.array_equal(x, out[0]) and np.array_equal(y, out[1]) and np.array_equal(z, out[2])
    back, = outputs(tmp_path, "ColorTransform", {"INPUT": expected}, "OUTPUT",
                    transform="XYZ->RGB", scale=2, ignore_transform="no")
    assert np.allclose(back, image, atol=1e-4)


def test_rgb_to_rgi(tmp_path):
    image = pixels((0.6, 0.3, 0.3), (0, 0, 0), (0.1, 0.2, 0.7))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT", transform="RGB->rgI",
                   ignore_transform="no")
    assert np.allclose(out[0, 0], [0.5, 1 / 3, 0.1], atol=1e-6)   # black: 1/3
    assert np.allclose(out[1, 0], [0.25, 1 / 3, 0.2], atol=1e-6)
    assert np.allclose(out[2, 0], [1.2, 0, 1.0], atol=1e-6)       # I = R + G + B
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image * 255}, "OUTPUT",
                   transform="RGB->rgI", scale=255, ignore_transform="no")
    assert np.allclose(out[2, 0], [1.2, 0, 1.0], atol=1e-6)


def test_ikaros2_ignores_transform_and_ikaros3_uses_it(tmp_path):
    """Ikaros 2's golden outputs: every transform gives RGB->Lab; Ikaros 3's: the one named."""
    image = RNG.random((3, 2, 3)).astype(np.float32)
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": image}, "OUTPUT",
                   transform="RGB->XYZ")
    assert np.allclose(out, lab(image), atol=2e-3)
    body = (f'<module class="Constant" name="C" data="{literal(image)}"/>'
            '<module class="ColorTransform" name="T" transform="RGB->XYZ"/>'
            '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>')
    with load_body(tmp_path, body, dialect=3) as net:
        net.step()
        assert np.allclose(net.output("T.OUTPUT"), np.einsum("ij,jrc->irc", M, image),
                           atol=1e-5)


def test_lab_is_single_precision_as_the_original(tmp_path):
    """A grey's a and b come from the float rounding of its X, Y and Z: computed here in
    float32 with the original's matrix (whose rows sum to the white) over the white, they
    are the golden files' values (a of 0.3 grey 0.0002086 in Ikaros 2, of 0.5 grey
    0.0002682 in Ikaros 3)."""
    grey = pixels((0.3, 0.3, 0.3), (0.5, 0.5, 0.5))
    out, = outputs(tmp_path, "ColorTransform", {"INPUT": grey}, "OUTPUT")
    original = np.array([[0.412453, 0.357581, 0.180423], [0.212670, 0.715160, 0.072169],
                         [0.019334, 0.119193, 0.950227]])
    m = (original / WHITE[:, None]).astype(np.float32)
    v = grey.astype(np.float32)
    xyz = [(v[0] * m[k, 0] + v[1] * m[k, 1]) + v[2] * m[k, 2] for k in range(3)]
    f = [np.cbrt(t) for t in xyz]                       # all above 0.008856
    a, b = (f[0] - f[1]) * np.float32(500), (f[1] - f[2]) * np.float32(200)
    assert np.array_equal(out[1], a) and np.array_equal(out[2], b)
    assert np.allclose(out[1, 0], [0.0002086163, 0.0002682209], rtol=1e-6)


def test_partial_plane_inputs_are_a_model_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="connect either INPUT"):
        run(tmp_path, "ColorTransform", {"INPUT0": np.zeros((2, 2)), "INPUT": pixels((1, 1, 1))})


def classify(tmp_path, image, **params):
    """rgI through ColorTransform, then ColorClassifier."""
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = (f'<module class="Constant" name="C" data="{literal(image)}"/>'
            '<module class="ColorTransform" name="T" transform="RGB->rgI" '
            'ignore_transform="no"/>'
            f'<module class="ColorClassifier" name="K" {attrs}/>'
            '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>'
            '<connection source="T.OUTPUT0" target="K.R" delay="0"/>'
            '<connection source="T.OUTPUT1" target="K.G" delay="0"/>'
            '<connection source="T.OUTPUT2" target="K.I" delay="0"/>')
    with load_body(tmp_path, body) as net:
        net.step()
        return [net.output(f"K.{n}") for n in ("OUTPUT", "COLORSPACE_R", "COLORSPACE_G",
                                                 "COLORSPACE_B")]


def hue_pixel(hue, saturation, intensity=1.0):
    """An (r, g, b) colour whose rg chromaticity lies ``saturation`` from white in the
    class file's direction (sin hue, cos hue) of the plane (r - 1/3, g - 1/3)."""
    t = np.radians(hue)
    r, g = 1 / 3 + saturation * np.sin(t), 1 / 3 + saturation * np.cos(t)
    return tuple(intensity * np.array([r, g, 1 - r - g]))


def test_classifier_hue_is_the_class_files_direction(tmp_path):
    # red r = 2/3, g = 0 (hue 135); green r = 0, g = 2/3 (315); blue r = g = 1/7 (225)
    colours = [(2, 0, 1), (0, 2, 1), (0.1, 0.1, 0.5), (0.5, 0.5, 0.5)]
    image = pixels(*colours)
    out, *_ = classify(tmp_path, image, color=135)
    assert np.array_equal(out[0], [1, 0, 0, 0])        # color="135" selects red
    out, *_ = classify(tmp_path, image, color=315)
    assert np.array_equal(out[0], [0, 1, 0, 0])
    out, *_ = classify(tmp_path, image)                # the default 225: blue
    assert np.array_equal(out[0], [0, 0, 1, 0])
    out, *_ = classify(tmp_path, image, saturation_min=0, width=180)
    assert np.array_equal(out[0], [1, 1, 1, 0])        # gray: saturation 0 is not above 0


def test_classifier_width_is_either_side_and_saturation_bounds_are_strict(tmp_path):
    image = pixels(hue_pixel(225 + 19.9, 0.3), hue_pixel(225 - 19.9, 0.3),
                   hue_pixel(225 + 20.1, 0.3), hue_pixel(225, 0.051), hue_pixel(225, 0.049),
                   hue_pixel(225, 0.499), hue_pixel(225, 0.501))
    out, *_ = classify(tmp_path, image)                # width 20, saturation 0.05 .. 0.5
    assert np.array_equal(out[0], [1, 1, 0, 1, 0, 1, 0])


def test_classifier_bounds_to_the_last_bit_in_a_mostly_gray_image(tmp_path):
    # a gray image with rows of chromaticities that step one float32 at a time across the
    # saturation bounds (0.05, 0.5) and the hue bounds (117 +- 15): the selection is the
    # test in float32, d . u >= |d| cos(width) and 0.05 < |d| < 0.5, pixel for pixel
    third = np.float32(1 / 3)
    r = np.full((48, 64), third, np.float32)
    g = r.copy()
    steps = np.arange(-32, 32, dtype=np.float32)
    for row, (hue, sat) in enumerate([(117, 0.05), (117, 0.5), (102, 0.2), (132, 0.2),
                                      (90, 0.05), (300, 0.3)]):
        t = np.radians(hue)
        r0 = np.float32(1 / 3 + sat * np.sin(t))
        r[8 * row] = r0 + steps * np.spacing(r0)
        g[8 * row] = np.float32(1 / 3 + sat * np.cos(t))
    out, = outputs(tmp_path, "ColorClassifier", {"R": r, "G": g, "I": r + g},
                   "OUTPUT", color="117", width="15", diagnostics="no")
    dr, dg = r - third, g - third
    sat = np.hypot(dr, dg)
    c, w = np.radians(117), np.radians(15)
    along = dr * np.float32(np.sin(c)) + dg * np.float32(np.cos(c))
    expected = ((along >= sat * np.float32(np.cos(w))) & (sat > np.float32(0.05))
                & (sat < np.float32(0.5)))
    assert 0 < expected.sum() < 64 * 3
    assert np.array_equal(out, expected.astype(np.float32))


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


def chroma_distance(image, colour):
    """The distance of each pixel's colour divided by its sum from ``colour`` divided by
    its sum (the issue's and the golden files' ColorMatch)."""
    colour = np.asarray(colour, float)
    total = image.sum(axis=0)
    return np.sqrt(((image / total - (colour / colour.sum())[:, None, None]) ** 2).sum(axis=0))


def test_color_match_similarity(tmp_path):
    image = RNG.uniform(0, 100, (3, 4, 6)).astype(np.float32)
    image[:, 0, 0] = (0.1, 0.1, 0.1)                     # sum 0.3: not above the threshold
    image[:, 0, 1] = (5, 10, 15)                         # the target's chromaticity
    out, = outputs(tmp_path, "ColorMatch", {"INPUT": image}, "OUTPUT", target0=50,
                   target1=100, target2=150, sigma=3, gain=2, threshold=0.5,
                   similarity="graded")
    expected = 2 * np.exp(-3 * chroma_distance(image, (50, 100, 150)))
    expected[0, 0] = 0
    assert out[0, 1] == pytest.approx(2, abs=1e-5)
    assert np.allclose(out, expected, atol=1e-5)
    assert (out[expected > 0] < 0.5).any()               # values below the threshold stay


def test_color_match_learns_the_colour_at_the_focus(tmp_path):
    image = np.ones((3, 4, 4), np.float32)
    image[:, 1, 3] = (10, 20, 30)                      # x = 0.9, y = 0.3 is in this pixel
    inputs = {"INPUT0": image[0], "INPUT1": image[1], "INPUT2": image[2],
              "FOCUS": [0.9, 0.3], "REINFORCEMENT": [0.5]}
    with run(tmp_path, "ColorMatch", inputs, ticks=0, alpha=0.2, sigma=10, target0=4,
             target1=2, target2=2, similarity="graded") as net:
        net.step()                                     # OUTPUT from the starting prototype
        assert np.allclose(net.output("M.OUTPUT"),
                           np.exp(-10 * chroma_distance(image, (4, 2, 2))), atol=1e-6)
        net.step()                                     # and then from the learned one:
        start = np.array([0.5, 0.25, 0.25])            # the prototype divided by its sum
        learned = start + 0.1 * (np.array([10, 20, 30]) - start)  # alpha * reinforcement
        assert np.allclose(net.output("M.OUTPUT"),
                           np.exp(-10 * chroma_distance(image, learned)), atol=1e-6)
        net.run(ticks=50)
        assert net.output("M.OUTPUT")[1, 3] == pytest.approx(1.0, abs=1e-5)


def test_color_match_binary_as_ikaros2(tmp_path):
    """Ikaros 2 (the default in its files): gain where the sum is above the threshold and
    exp(-sigma · d²) is a normal float32 above it, d² the squared distance of the colours
    divided by their sums."""
    image = RNG.uniform(-0.5, 1.0, (3, 5, 6)).astype(np.float32)
    image[:, 0, 0] = (0.1, 0.0, -0.1)                  # sum 0
    out, = outputs(tmp_path, "ColorMatch", {"INPUT": image}, "OUTPUT", target0=0.3,
                   target1=0.6, target2=0.4, sigma=25, gain=3)
    total = image.sum(axis=0, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        d2 = chroma_distance(image, (0.3, 0.6, 0.4)) ** 2
        expected = np.where((total > 0) & (25 * d2 < -np.log(np.finfo(np.float32).tiny)),
                            3.0, 0.0)
    assert set(np.unique(out)) <= {0.0, 3.0}
    assert out[0, 0] == 0
    assert np.array_equal(out, expected)
