"""Tests of Dilate, Erode, IntegralImage, Downsample, Upsample and WhiteBalance."""
import numpy as np
import pytest
from numpy.lib.stride_tricks import sliding_window_view

import ikaros
from ikaros.testing import load_body
from vision_models import literal, outputs, run

RNG = np.random.default_rng(3)
GRAY = RNG.random((9, 12)).astype(np.float32)
COLOUR = RNG.random((3, 7, 9)).astype(np.float32)


def windows(image):
    return sliding_window_view(image, (3, 3), axis=(-2, -1))


def test_dilate_and_erode_are_the_3x3_maximum_and_minimum(tmp_path):
    dilated, = outputs(tmp_path, "Dilate", {"INPUT": COLOUR}, "OUTPUT")
    eroded, = outputs(tmp_path, "Erode", {"INPUT": GRAY}, "OUTPUT")
    assert dilated.shape == (3, 5, 7) and eroded.shape == (7, 10)
    assert np.array_equal(dilated, windows(COLOUR).max(axis=(-2, -1)))
    assert np.array_equal(eroded, windows(GRAY).min(axis=(-2, -1)))


def test_dilate_grows_and_erode_shrinks_a_square(tmp_path):
    image = np.zeros((10, 10), np.float32)
    image[3:7, 3:7] = 1                              # a 4 x 4 square
    dilated, = outputs(tmp_path, "Dilate", {"INPUT": image}, "OUTPUT")
    eroded, = outputs(tmp_path, "Erode", {"INPUT": image}, "OUTPUT")
    grown, shrunk = np.zeros((10, 10)), np.zeros((10, 10))
    grown[2:8, 2:8] = 1
    shrunk[4:6, 4:6] = 1
    assert np.array_equal(dilated, grown[1:-1, 1:-1])
    assert np.array_equal(eroded, shrunk[1:-1, 1:-1])


def test_integral_image_is_the_summed_area_table(tmp_path):
    table, = outputs(tmp_path, "IntegralImage", {"INPUT": GRAY}, "OUTPUT")
    assert np.allclose(table, GRAY.astype(np.float64).cumsum(0).cumsum(1), atol=1e-5)
    ones, = outputs(tmp_path, "IntegralImage", {"INPUT": np.ones((3, 6, 5))}, "OUTPUT")
    rows, cols = np.meshgrid(np.arange(1, 7), np.arange(1, 6), indexing="ij")
    assert np.array_equal(ones, np.stack([rows * cols] * 3))
    # the sum over any rectangle from four table entries
    t = table
    assert t[7, 10] - t[2, 10] - t[7, 4] + t[2, 4] == pytest.approx(
        float(GRAY[3:8, 5:11].sum()), abs=1e-4)


def test_downsample_subsample_takes_every_second_pixel(tmp_path):
    image = np.arange(35, dtype=np.float32).reshape(5, 7)
    out, = outputs(tmp_path, "Downsample", {"INPUT": image}, "OUTPUT", method="subsample")
    assert np.array_equal(out, [[0, 2, 4], [14, 16, 18]])   # rows 0, 2; columns 0, 2, 4
    out, = outputs(tmp_path, "Downsample", {"INPUT": COLOUR}, "OUTPUT", method="subsample")
    assert np.array_equal(out, COLOUR[:, 0:6:2, 0:8:2])


def test_downsample_takes_the_mean_of_2x2_blocks_by_default(tmp_path):
    out, = outputs(tmp_path, "Downsample", {"INPUT": GRAY[:, :11]}, "OUTPUT")
    assert out.shape == (4, 5)
    blocks = GRAY[:8, :10].reshape(4, 2, 5, 2).mean(axis=(1, 3))
    assert np.allclose(out, blocks, atol=1e-6)
    out, = outputs(tmp_path, "Downsample", {"INPUT": COLOUR}, "OUTPUT")
    assert out.shape == (3, 3, 4)
    assert np.allclose(out, COLOUR[:, :6, :8].reshape(3, 3, 2, 4, 2).mean(axis=(2, 4)),
                       atol=1e-6)


def test_upsample_repeats_pixels(tmp_path):
    out, = outputs(tmp_path, "Upsample", {"INPUT": COLOUR}, "OUTPUT")
    assert out.shape == (3, 14, 18)
    assert np.array_equal(out, COLOUR.repeat(2, axis=1).repeat(2, axis=2))
    back, = outputs(tmp_path, "Downsample", {"INPUT": out}, "OUTPUT")
    assert np.allclose(back, COLOUR, atol=1e-6)


def test_white_balance_brings_the_reference_region_to_the_target(tmp_path):
    image = np.stack([np.full((30, 20), v, np.float32) for v in (0.8, 0.5, 0.4)])
    image[:, 20, 10] = (0.5, 0.25, 0.2)              # the region x 10..10, y 20..20
    out, red, green, blue = outputs(tmp_path, "WhiteBalance", {"INPUT": image}, "OUTPUT",
                                    "OUTPUT0", "OUTPUT1", "OUTPUT2", red_target=1,
                                    green_target=1, blue_target=0.4, x1=11, y1=21)
    gains = np.array([1 / 0.5, 1 / 0.25, 0.4 / 0.2])[:, None, None]  # targets in 0..1 units
    assert np.allclose(out, image * gains, atol=1e-6)
    assert np.allclose(out[:, 20, 10], (1.0, 1.0, 0.4), atol=1e-6)
    assert np.array_equal(red, out[0]) and np.array_equal(green, out[1])
    assert np.array_equal(blue, out[2])


def test_white_balance_region_ends_are_exclusive(tmp_path):
    planes = {f"INPUT{i}": COLOUR[i] for i in range(3)}
    out0, out2 = outputs(tmp_path, "WhiteBalance", planes, "OUTPUT0", "OUTPUT2", x0=2, x1=4,
                         y0=1, y1=3)
    # columns 2 and 3, rows 1 and 2; the default target 255
    assert np.allclose(out0, 255 * COLOUR[0] / COLOUR[0, 1:3, 2:4].mean(), rtol=1e-5)
    assert np.allclose(out2, 255 * COLOUR[2] / COLOUR[2, 1:3, 2:4].mean(), rtol=1e-5)


def test_white_balance_zero_mean_gives_zero_and_empty_region_nan(tmp_path):
    image = np.stack([np.full((4, 4), v, np.float32) for v in (0.5, 0.0, 0.25)])
    image[1, 3, 3] = 0.7                             # green is 0 in the region only
    out, = outputs(tmp_path, "WhiteBalance", {"INPUT": image}, "OUTPUT", x0=0, x1=2, y0=0,
                   y1=2, red_target=1, green_target=1, blue_target=1)
    assert np.allclose(out[0], 1) and np.allclose(out[2], 1) and not out[1].any()
    with run(tmp_path, "WhiteBalance", {"INPUT": image}) as net:   # Ikaros 2's defaults:
        assert np.isnan(net.output("M.OUTPUT")).all()             # an empty region
        assert any("has no pixel" in m for *_, m in net.log)


def test_white_balance_logs_the_colour_of_its_log_region(tmp_path, capsys):
    planes = {f"INPUT{i}": COLOUR[i] for i in range(3)}
    with run(tmp_path, "WhiteBalance", planes, x0=0, x1=2, y0=0, y1=2, red_target=1,
             green_target=1, blue_target=1, log_x0=1, log_x1=3, log_y0=2,
             log_y1=4) as net:
        out = net.output("M.OUTPUT")
    before = COLOUR[:, 2:4, 1:3].mean(axis=(1, 2))
    after = out[:, 2:4, 1:3].mean(axis=(1, 2))
    text = capsys.readouterr().out
    assert "log region RGB " + " ".join(f"{v:.6g}" for v in before) in text
    assert " ".join(f"{v:.6g}" for v in after) in text


def test_white_balance_in_an_ikaros3_file_has_ikaros3_defaults(tmp_path):
    body = (f'<module class="Constant" name="C" data="{literal(COLOUR)}"/>'
            '<module class="WhiteBalance" name="M" x1="3"/>'
            '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    with load_body(tmp_path, body, dialect=3) as net:
        net.step()
        out = net.output("M.OUTPUT")
    # targets 1, region row 0 (y0 = 0, y1 = 1), columns 0..2 (x0 = 0 by default, x1 set)
    means = COLOUR[:, 0:1, 0:3].mean(axis=(1, 2))[:, None, None]
    assert np.allclose(out, COLOUR / means, rtol=1e-5)


def test_white_balance_needs_one_kind_of_input(tmp_path):
    with pytest.raises(ikaros.ModelError, match="connect either INPUT"):
        run(tmp_path, "WhiteBalance", {"INPUT0": GRAY, "INPUT1": GRAY})
