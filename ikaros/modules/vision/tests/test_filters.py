"""Tests of the kernel filters: GaussianFilter, DoGFilter, LoGFilter, GaborFilter,
MedianFilter and ImageConvolution, each against an independent computation (SciPy)."""
import math
import sys

import numpy as np
import pytest
from scipy import ndimage, signal

import ikaros
from vision_models import outputs, run

RNG = np.random.default_rng(7)
GRAY = RNG.random((12, 14)).astype(np.float32)
COLOUR = RNG.random((3, 10, 11)).astype(np.float32)


def valid(image, kernel):
    """Correlation of each plane with the kernel where the kernel fits (float64)."""
    k = np.asarray(kernel, np.float64)
    if image.ndim == 2:
        return signal.correlate2d(image.astype(np.float64), k, mode="valid")
    return np.stack([valid(p, k) for p in image])


def test_gaussian_kernel_sums_to_one_with_a_gaussian_profile(tmp_path):
    out, kernel, profile = outputs(tmp_path, "GaussianFilter", {"INPUT": GRAY}, "OUTPUT",
                                   "KERNEL", "PROFILE", sigma=1.5, kernel_size=7)
    x = np.arange(7) - 3
    expected = np.exp(-x ** 2 / (2 * 1.5 ** 2))
    expected /= expected.sum()
    assert profile.shape == (1, 7) and kernel.shape == (7, 7)
    assert kernel.sum() == pytest.approx(1.0, abs=1e-5)
    assert np.allclose(kernel, np.outer(expected, expected), atol=1e-7)
    # PROFILE is the middle row of KERNEL, as Ikaros 2's golden outputs show
    assert np.allclose(profile[0], expected * expected[3], atol=1e-7)
    assert out.shape == (6, 8)                      # 12 - 7 + 1, 14 - 7 + 1
    assert np.allclose(out, valid(GRAY, kernel), atol=1e-5)


def test_gaussian_filters_colour_plane_by_plane(tmp_path):
    out, kernel = outputs(tmp_path, "GaussianFilter", {"INPUT": COLOUR}, "OUTPUT", "KERNEL")
    assert out.shape == (3, 6, 7)
    assert np.allclose(out, valid(COLOUR, kernel), atol=1e-5)


def test_gaussian_keeps_a_flat_image_and_follows_sigma_changes(tmp_path):
    with run(tmp_path, "GaussianFilter", {"INPUT": GRAY}) as net:
        net.set_parameter("M.sigma", 0.7)
        net.step()
        x = np.arange(5) - 2
        g = np.exp(-x ** 2 / (2 * 0.7 ** 2))
        assert np.allclose(net.output("M.PROFILE")[0], g * g[2] / g.sum() ** 2, atol=1e-6)
        assert np.allclose(net.output("M.OUTPUT"), valid(GRAY, np.outer(g, g) / g.sum() ** 2),
                           atol=1e-5)
    (flat,) = outputs(tmp_path, "GaussianFilter", {"INPUT": np.full((6, 6), 0.25)}, "OUTPUT")
    assert np.allclose(flat, 0.25, atol=1e-6)


def test_even_kernel_size_is_a_model_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="kernel_size must be a positive odd number"):
        run(tmp_path, "GaussianFilter", {"INPUT": GRAY}, kernel_size=4)


def test_kernel_larger_than_the_image_is_a_model_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="smaller than the kernel"):
        run(tmp_path, "GaussianFilter", {"INPUT": GRAY[:3, :3]})


def test_a_vector_is_a_one_row_image(tmp_path):
    # as in Ikaros 2, where every array is a matrix: here too small for the 5 x 5 kernel
    with pytest.raises(ikaros.ModelError, match="the image \\(1 x 8\\) is smaller than"):
        run(tmp_path, "GaussianFilter", {"INPUT": np.arange(8.0)})
    out, = outputs(tmp_path, "GaussianFilter", {"INPUT": np.arange(8.0)}, "OUTPUT",
                   kernel_size=1)
    assert np.allclose(out, [np.arange(8.0)])


def gaussian(r2, sigma, pi=math.pi):
    """A Gaussian with the 1-D constant 1 / (sigma sqrt(2 pi)); Ikaros 2's DoGFilter takes
    pi as 3 (its golden outputs)."""
    return np.exp(-r2 / (2 * sigma ** 2)) / (sigma * math.sqrt(2 * pi))


def grid(size):
    x = np.arange(size) - size // 2
    return x[None, :] ** 2 + x[:, None] ** 2


def balanced(kernel):
    """Positive entries scaled to sum 1, negative ones to sum -1."""
    positive, negative = kernel > 0, kernel < 0
    return np.where(positive, kernel / kernel[positive].sum(),
                    np.where(negative, kernel / -kernel[negative].sum(), 0.0))


def test_dog_normalize_scales_positive_and_negative_parts_apart(tmp_path):
    out, kernel, profile = outputs(tmp_path, "DoGFilter", {"INPUT": GRAY}, "OUTPUT", "KERNEL",
                                   "PROFILE")
    expected = balanced(gaussian(grid(5), 1.0) - gaussian(grid(5), 0.5))
    assert np.allclose(kernel, expected, atol=1e-6)
    assert kernel[kernel > 0].sum() == pytest.approx(1.0, abs=1e-6)
    assert kernel[kernel < 0].sum() == pytest.approx(-1.0, abs=1e-6)
    assert np.array_equal(profile[0], kernel[2])
    assert out.shape == (8, 10) and np.allclose(out, valid(GRAY, expected), atol=1e-5)


def test_dog_without_normalize_uses_the_1d_constant_with_pi_3(tmp_path):
    (kernel,) = outputs(tmp_path, "DoGFilter", {"INPUT": GRAY}, "KERNEL", normalize="no")
    # at the centre: 1/sqrt(6) - 1/(0.5 sqrt(6)) = -0.408248
    assert kernel[2, 2] == pytest.approx(-1 / math.sqrt(6), abs=1e-6)
    assert np.allclose(kernel, gaussian(grid(5), 1, 3) - gaussian(grid(5), 0.5, 3),
                       atol=1e-6)
    (kernel,) = outputs(tmp_path, "DoGFilter", {"INPUT": GRAY}, "KERNEL", normalize="no",
                        pi="exact")
    # at the centre: 1/sqrt(2 pi) - 1/(0.5 sqrt(2 pi)) = -0.398942
    assert kernel[2, 2] == pytest.approx(-0.398942, abs=1e-6)
    assert np.allclose(kernel, gaussian(grid(5), 1) - gaussian(grid(5), 0.5), atol=1e-6)


def test_log_kernel_and_response_to_a_bright_spot(tmp_path):
    image = np.zeros((9, 9), np.float32)
    image[4, 4] = 1.0
    out, kernel = outputs(tmp_path, "LoGFilter", {"INPUT": image}, "OUTPUT", "KERNEL",
                          normalize="no")
    r2 = grid(5)
    expected = (r2 - 2) * np.exp(-r2 / 2) / (2 * np.pi)
    assert np.allclose(kernel, expected, atol=1e-6)
    assert out.shape == (5, 5)
    assert out[2, 2] == pytest.approx(expected[2, 2], abs=1e-6) and out[2, 2] < 0
    (normalised,) = outputs(tmp_path, "LoGFilter", {"INPUT": GRAY}, "KERNEL")
    assert np.allclose(normalised, balanced(expected), atol=1e-6)
    assert normalised[normalised < 0].sum() == pytest.approx(-1.0, abs=1e-6)
    assert normalised[2, 2] == pytest.approx(-2 / (2 * np.pi) / -expected[expected < 0].sum())


def gabor(size, theta=0.0, phi=1.57, sigma=1.0, wavelength=4.0, gamma=0.5):
    c = np.arange(size) - size // 2
    x, y = c[None, :], c[:, None]
    xr, yr = x * math.cos(theta) + y * math.sin(theta), -x * math.sin(theta) + y * math.cos(theta)
    envelope = np.exp(-(xr ** 2 + gamma ** 2 * yr ** 2) / (2 * sigma ** 2))
    return envelope, np.cos(2 * np.pi * xr / wavelength + phi)


def test_gabor_is_5x5_by_default_and_rectified(tmp_path):
    image = RNG.random((9, 10)).astype(np.float32) - 0.5   # a 9 x 10 image is enough
    out, filt, envelope, grating = outputs(tmp_path, "GaborFilter", {"INPUT": image},
                                           "OUTPUT", "FILTER", "GAUSSIAN", "GRATING",
                                           theta=0.5, phi=0.3)
    expected_envelope, expected_grating = gabor(5, theta=0.5, phi=0.3)
    assert filt.shape == (5, 5)
    assert np.allclose(envelope, expected_envelope, atol=1e-6)
    assert np.allclose(grating, expected_grating, atol=1e-6)
    assert np.allclose(filt, envelope * grating, atol=1e-6)
    assert out.shape == (5, 6)
    correlation = valid(image, filt)
    assert (correlation < 0).any()
    assert np.allclose(out, np.abs(correlation), atol=1e-5)


@pytest.mark.parametrize("scale, size", [(1.3, 7), (0.2, 1), (0.25, 3), (2, 9)])
def test_gabor_scale_sets_only_the_size(tmp_path, scale, size):
    filt, = outputs(tmp_path, "GaborFilter", {"INPUT": np.zeros((12, 12))}, "FILTER",
                    scale=scale)                       # radius int(2 scale + 0.5)
    envelope, grating = gabor(size)                    # sigma and lambda not scaled
    assert np.allclose(filt, envelope * grating, atol=1e-6)


@pytest.mark.parametrize("size", [3, 5, 7])
def test_median_matches_scipy(tmp_path, size):
    (out,) = outputs(tmp_path, "MedianFilter", {"INPUT": GRAY}, "OUTPUT", kernel_size=size)
    b = size // 2
    expected = ndimage.median_filter(GRAY, size=size)[b:-b, b:-b]
    assert out.shape == (12 - size + 1, 14 - size + 1)
    assert np.array_equal(out, expected)


def test_median_removes_salt_noise(tmp_path):
    image = np.full((8, 8), 0.5, np.float32)
    image[3, 4] = 1.0
    (out,) = outputs(tmp_path, "MedianFilter", {"INPUT": image}, "OUTPUT", kernel_size=3)
    assert np.array_equal(out, np.full((6, 6), 0.5, np.float32))


def test_convolution_applies_the_kernel_as_written_scales_biases_rectifies(tmp_path):
    # not flipped, as Ikaros 2's golden outputs show
    kernel = np.array([[1, 2, 0], [0, -1, 3]], np.float32)
    (out,) = outputs(tmp_path, "ImageConvolution", {"INPUT": COLOUR}, "OUTPUT",
                     kernel="1 2 0; 0 -1 3", scale=2, bias=-1.5, rectify="yes")
    expected = valid(COLOUR, kernel)
    assert out.shape == (3, 9, 9)
    assert ((2 * expected - 1.5) < -0.5).any()          # negatives become positive
    assert np.allclose(out, np.abs(2 * expected - 1.5), atol=1e-5)


def test_convolution_kernel_can_change_but_not_its_size(tmp_path):
    with run(tmp_path, "ImageConvolution", {"INPUT": GRAY}, kernel="1 0; 0 0") as net:
        assert np.allclose(net.output("M.OUTPUT"), GRAY[:-1, :-1])
        net.set_parameter("M.kernel", "0 0; 0 2")
        net.step()
        assert np.allclose(net.output("M.OUTPUT"), 2 * GRAY[1:, 1:])
        net.set_parameter("M.kernel", "1 0 0")
        net.step()
        assert np.allclose(net.output("M.OUTPUT"), 2 * GRAY[1:, 1:])
        assert any("cannot change while the model runs" in m for *_, m in net.log)


def test_convolution_without_a_kernel_is_empty_as_the_original(tmp_path):
    # Ikaros 2 gives kernel no default: an empty kernel, an output one larger, holding bias
    with run(tmp_path, "ImageConvolution", {"INPUT": GRAY}, bias=-0.5, rectify="yes") as net:
        assert np.array_equal(net.output("M.OUTPUT"), np.full((13, 15), 0.5))
        assert any("no kernel is set" in m for *_, m in net.log)


def test_missing_opencv_names_the_install(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "cv2", None)      # import cv2 now fails
    with pytest.raises(ikaros.ModelError, match=r"pip install 'ikaros\[vision\]'"):
        run(tmp_path, "GaussianFilter", {"INPUT": GRAY})
