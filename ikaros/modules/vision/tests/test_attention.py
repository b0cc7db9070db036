"""Tests of AttentionFocus, AttentionWindow, SaliencePoints and SaliencyMap."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body
from vision_models import literal, outputs, run

RNG = np.random.default_rng(9)
IMAGE = RNG.random((3, 20, 30)).astype(np.float32)


def test_attention_focus_cuts_the_square_around_the_focus(tmp_path):
    # x = 12.5 / 30, y = 7.5 / 20: the centre of the pixel in row 7, column 12
    out, = outputs(tmp_path, "AttentionFocus", {"INPUT": IMAGE, "FOCUS": [12.5 / 30, 0.375]},
                   "OUTPUT", output_radius=3)
    assert out.shape == (3, 7, 7)
    assert np.array_equal(out, IMAGE[:, 4:11, 9:16])


def test_attention_focus_pads_outside_the_image_with_zeros(tmp_path):
    out, = outputs(tmp_path, "AttentionFocus", {"INPUT": IMAGE[0], "FOCUS": [0.0, 0.99]},
                   "OUTPUT", output_radius=2, edge="copied")
    expected = np.zeros((5, 5), np.float32)
    expected[:3, 2:] = IMAGE[0, 17:20, 0:3]           # row 19, column 0 is the centre
    assert np.array_equal(out, expected)
    # Ikaros 2 (its golden outputs) never copies the first row and column
    out, = outputs(tmp_path, "AttentionFocus", {"INPUT": IMAGE[0], "FOCUS": [0.0, 0.99]},
                   "OUTPUT", output_radius=2)
    expected[:, 2] = 0
    assert np.array_equal(out, expected)
    out, = outputs(tmp_path, "AttentionFocus", {"INPUT": IMAGE[0], "FOCUS": [0.99, 0.0]},
                   "OUTPUT", output_radius=1)
    assert not out[:2].any() and np.array_equal(out[2, :2], IMAGE[0, 1, 28:30])


def test_attention_focus_default_is_a_square_of_31(tmp_path):
    out, = outputs(tmp_path, "AttentionFocus", {"INPUT": IMAGE[0], "FOCUS": [0.5, 0.5]},
                   "OUTPUT")
    assert out.shape == (31, 31)
    assert np.array_equal(out[6:25, 1:30], IMAGE[0, 1:20, 1:30])   # centre row 10, col 15
    assert not out[:6].any() and not out[25:].any() and not out[:, 0].any()


def test_attention_window_resamples_the_top_down_bounds(tmp_path):
    # bounds covering columns 10..19 and rows 4..13 exactly, resampled to half: 2x2 means
    bounds = [10 / 30, 4 / 20, 20 / 30, 14 / 20]
    out, = outputs(tmp_path, "AttentionWindow", {"INPUT": IMAGE, "TOP_DOWN_BOUNDS": bounds},
                   "OUTPUT", output_size_x=5, output_size_y=5)
    assert out.shape == (3, 5, 5)
    block = IMAGE[:, 4:14, 10:20].reshape(3, 5, 2, 5, 2).mean(axis=(2, 4))
    assert np.allclose(out, block, atol=1e-5)


def test_attention_window_at_the_same_size_copies_and_pads(tmp_path):
    gray = IMAGE[1]
    position = [(2 + 0.5) / 30, (3 + 0.5) / 20]          # centre of row 3, column 2
    inputs = {"INPUT": gray, "BOTTOM_UP_POSITION": [position, [0.5, 0.5]],
              "BOTTOM_UP_COUNT": [2]}
    out, = outputs(tmp_path, "AttentionWindow", inputs, "OUTPUT", window_radius=3,
                   output_size_x=7, output_size_y=7)
    expected = np.zeros((7, 7), np.float32)
    expected[:, 1:] = gray[0:7, 0:6]
    assert np.allclose(out, expected, atol=1e-5)
    inputs["BOTTOM_UP_COUNT"] = [0]
    out, = outputs(tmp_path, "AttentionWindow", inputs, "OUTPUT")
    assert not out.any()


def test_attention_window_prefers_top_down_and_reads_corner_bounds(tmp_path):
    corners = [10 / 30, 4 / 20, 20 / 30, 4 / 20, 20 / 30, 14 / 20, 10 / 30, 14 / 20]
    inputs = {"INPUT": IMAGE[2], "BOTTOM_UP_BOUNDS": [corners],
              "TOP_DOWN_POSITION": [15 / 30, 9 / 20]}
    out, = outputs(tmp_path, "AttentionWindow", inputs, "OUTPUT", window_size_x=10,
                   window_size_y=10, output_size_x=10, output_size_y=10)
    assert np.allclose(out, IMAGE[2, 4:14, 10:20], atol=1e-5)
    del inputs["TOP_DOWN_POSITION"]
    out, = outputs(tmp_path, "AttentionWindow", inputs, "OUTPUT", output_size_x=10,
                   output_size_y=10)
    assert np.allclose(out, IMAGE[2, 4:14, 10:20], atol=1e-5)


def test_salience_points_adds_gaussian_blobs(tmp_path):
    # points at (x size_x, y size_y) = (4.5, 3.5) and (10, 6) pixels, saliences 2 and 0.5
    points = [[0, 4.5 / 12, 3.5 / 8, 2.0], [0, 10 / 12, 6 / 8, 0.5], [0, 0.1, 0.1, 9]]
    out, = outputs(tmp_path, "SaliencePoints", {"INPUT": points, "COUNT": [2]}, "OUTPUT",
                   size_x=12, size_y=8, sigma=1.5, select=1, select_salience=3, scale=3)
    rows, cols = np.mgrid[0:8, 0:12] + 0.5
    expected = sum(3 * s * np.exp(-((cols - x) ** 2 + (rows - y) ** 2) / (2 * 1.5 ** 2))
                   for x, y, s in ((4.5, 3.5, 2.0), (10.0, 6.0, 0.5)))
    assert out.shape == (8, 12)
    assert np.allclose(out, expected, atol=1e-5)
    assert out[3, 4] == pytest.approx(6.0, abs=1e-3)   # height scale x salience


def test_salience_points_are_fractions_of_the_map_with_scale_1(tmp_path):
    out, = outputs(tmp_path, "SaliencePoints", {"INPUT": [0.25, 0.75]}, "OUTPUT", size_x=8,
                   size_y=8, sigma=1)
    # the point is at (2, 6) pixels, the corner between columns 1, 2 and rows 5, 6
    assert np.unravel_index(np.argmax(out), out.shape) in ((5, 1), (5, 2), (6, 1), (6, 2))
    assert out[5, 1] == pytest.approx(np.exp(-0.25), abs=1e-6)
    assert out[5, 1] == pytest.approx(out[6, 2], abs=1e-6)


def test_salience_points_checks_the_columns(tmp_path):
    with pytest.raises(ikaros.ModelError, match="at least 4 columns"):
        run(tmp_path, "SaliencePoints", {"INPUT": [[1, 2, 3]]}, select_salience=3)


def saliency_model(tmp_path, maps, reinforcement=None, **params):
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = [f'<module class="SaliencyMap" name="S" no_of_inputs="{len(maps)}" {attrs}/>']
    for i, m in enumerate(maps):
        body.append(f'<module class="Constant" name="F{i}" data="{literal(m)}"/>')
        body.append(f'<connection source="F{i}.OUTPUT" target="S.INPUT{i}" delay="0"/>')
    if reinforcement is not None:
        body.append(f'<module class="Constant" name="R" data="{reinforcement}"/>')
        body.append('<connection source="R.OUTPUT" target="S.REINFORCEMENT" delay="0"/>')
    return load_body(tmp_path, "\n".join(body))


def test_saliency_map_sums_and_focuses_on_the_maximum(tmp_path):
    a, b = np.zeros((6, 8), np.float32), np.zeros((6, 8), np.float32)
    a[2, 5], b[4, 1] = 1.0, 0.8
    with saliency_model(tmp_path, [a, b]) as net:
        net.step()
        assert np.allclose(net.output("S.SALIENCE"), a + b)
        assert np.allclose(net.output("S.FOCUS"), [5.5 / 8, 2.5 / 6])
        assert np.allclose(net.output("S.GAIN"), [1, 1])
        # the feature means over the 5 x 5 square around (2, 5): rows 0..4, columns 3..7
        assert net.output("S.ESTIMATION")[0] == pytest.approx(1 / 25, abs=1e-6)


def test_saliency_gains_learn_which_feature_predicts_reward(tmp_path):
    a, b = np.zeros((6, 8), np.float32), np.zeros((6, 8), np.float32)
    a[2, 5], b[4, 1] = 1.0, 0.8
    with saliency_model(tmp_path, [a, b], reinforcement=0, alpha=5,
                        integration_radius=0) as net:
        net.step()                                     # focus on a: reward 0
        assert np.allclose(net.output("S.GAIN"), [1 - 5 * 1 * 1, 1])
        net.step()                                     # now b wins: its gain stays
        assert np.allclose(net.output("S.FOCUS"), [1.5 / 8, 4.5 / 6])
        assert net.output("S.GAIN")[1] == pytest.approx(1 - 5 * 0.8 * 0.8, abs=1e-6)


def test_saliency_random_choices_follow_the_salience(tmp_path):
    m = np.zeros((4, 4), np.float32)
    m[1, 2], m[3, 0] = 1.0, 0.9
    counts = {}
    with saliency_model(tmp_path, [m], type="boltzmann", temperature=0.1, seed=4) as net:
        for _ in range(300):
            net.step()
            focus = tuple(np.round(net.output("S.FOCUS") * 4 - 0.5).astype(int))
            counts[focus] = counts.get(focus, 0) + 1
    # p ∝ exp(s / 0.1): 1 : 0.37 for the two peaks, the 14 zeros share e^-10 each
    assert set(counts) <= {(2, 1), (0, 3)}
    assert counts[(2, 1)] / 300 == pytest.approx(1 / (1 + np.exp(-1)), abs=0.08)
    with saliency_model(tmp_path, [m], type="exponential", temperature=0.01, seed=1) as net:
        net.run(ticks=20)
        assert np.allclose(net.output("S.FOCUS"), [2.5 / 4, 1.5 / 4])


def test_attention_focus_needs_x_and_y(tmp_path):
    with pytest.raises(ikaros.ModelError, match="FOCUS must hold x and y"):
        run(tmp_path, "AttentionFocus", {"INPUT": IMAGE, "FOCUS": [0.5]})
