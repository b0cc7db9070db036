"""Tests of the motion modules: ChangeDetector, StaufferGrimson, BlockMatching and
DirectionDetector, on image sequences with a known answer."""
import numpy as np
import pytest

from ikaros.errors import ModelError

from sequences import load_sequence, run_sequence

cv2 = pytest.importorskip("cv2")


def test_change_detector_gives_the_absolute_difference_inside_the_border(tmp_path):
    rng = np.random.default_rng(1)
    frames = rng.random((3, 10, 12)).astype(np.float32)
    out = run_sequence(tmp_path, frames, '<module class="ChangeDetector" name="M" border="2" '
                       'difference="exact"/>', "OUTPUT")
    assert out[0][0].shape == (6, 8)
    assert np.array_equal(out[0][0], frames[0][2:-2, 2:-2])   # the previous image is 0
    for k in (1, 2):
        assert np.allclose(out[k][0], np.abs(frames[k] - frames[k - 1])[2:-2, 2:-2], atol=0)


def test_change_detector_truncates_the_difference_as_ikaros2(tmp_path):
    frames = np.array([[[0.5, -1.0, 2.7, 0.25]], [[1.75, -1.0, 0.5, -3.5]]], np.float32)
    out = run_sequence(tmp_path, frames, '<module class="ChangeDetector" name="M"/>', "OUTPUT")
    assert np.array_equal(out[0][0], [[0, 1, 2, 0]])          # the golden files' first tick
    assert np.array_equal(out[1][0], [[1, 0, 2, 3]])          # 1.25, 0, 2.2, 3.75


def test_change_detector_on_colour(tmp_path):
    frames = np.zeros((2, 3, 4, 5), np.float32)
    frames[1, 1, 2, 3] = 0.75
    out = run_sequence(tmp_path, frames, '<module class="ChangeDetector" name="M" '
                       'difference="exact"/>', "OUTPUT")
    assert out[1][0].shape == (3, 4, 5) and out[1][0].sum() == 0.75 and out[1][0][1, 2, 3] == 0.75


def test_change_detector_border_too_large(tmp_path):
    with pytest.raises(ModelError, match="border 5 leaves nothing"):
        run_sequence(tmp_path, np.zeros((1, 8, 8)), '<module class="ChangeDetector" name="M" '
                     'border="5"/>', "OUTPUT")


def test_stauffer_grimson_finds_a_new_object_and_learns_it(tmp_path):
    rng = np.random.default_rng(2)
    background = rng.uniform(0.2, 0.8, (20, 24)).astype(np.float32)
    frames = [background + rng.normal(0, 0.005, background.shape) for _ in range(30)]
    for _ in range(3):
        f = background + rng.normal(0, 0.005, background.shape)
        f[5:10, 6:14] = 0.95                         # an object appears
        frames.append(f)
    frames = np.array(frames, np.float32)
    out = run_sequence(tmp_path, frames, '<module class="StaufferGrimson" name="M" '
                       'alpha="0.05" match="exact"/>', "OUTPUT")
    assert all(out[k][0].sum() == 0 for k in range(30))      # the noisy background
    expected = np.zeros(background.shape)
    expected[5:10, 6:14] = 1
    assert np.array_equal(out[30][0], expected)
    # an object that stays becomes background: with alpha 0.5 a few frames suffice
    with_object = background.copy()
    with_object[5:10, 6:14] = 0.95
    still = np.array([background] * 5 + [with_object] * 12, np.float32)
    out = run_sequence(tmp_path, still, '<module class="StaufferGrimson" name="M" '
                       'alpha="0.5" match="exact"/>', "OUTPUT")
    assert out[5][0].sum() == 40 and out[-1][0].sum() == 0


def textured(rows, cols, seed=3):
    rng = np.random.default_rng(seed)
    small = rng.random((rows // 4, cols // 4)).astype(np.float32)
    return cv2.resize(small, (cols, rows), interpolation=cv2.INTER_LINEAR)


def test_block_matching_finds_a_known_shift(tmp_path):
    image = textured(80, 96)
    shifted = np.roll(image, (3, -5), axis=(0, 1))            # down 3, left 5
    frames = np.array([image, shifted], np.float32)
    points = np.array([[30, 30], [50, 40], [60, 25]], np.float32)
    body = ('<module class="Constant" name="P" data="30 30; 50 40; 60 25"/>'
            '<module class="BlockMatching" name="M" block_radius="4" '
            'search_window_radius="8"/>'
            '<connection source="F.OUTPUT" target="M.INPUT" delay="0"/>'
            '<connection source="F.OUTPUT" target="M.INPUT-LAST" delay="1"/>'
            '<connection source="P.OUTPUT" target="M.POINTS" delay="0"/>')
    with load_sequence(tmp_path, frames, body) as net:
        net.step()
        net.step()
        flow = net.output("M.FLOW")
        assert flow.shape == (3, 4)
        assert np.array_equal(flow[:, :2], points)
        assert np.array_equal(flow[:, 2:], [[-5, 3]] * 3)
        assert net.output("M.FLOW-SIZE")[0] == 3
        assert net.output("M.DEBUG").shape == (240, 320)


def test_block_matching_counts_only_no_of_points(tmp_path):
    image = textured(64, 64)
    frames = np.array([image, np.roll(image, 2, axis=1)], np.float32)
    body = ('<module class="Constant" name="P" data="30 30; 0 0"/>'
            '<module class="Constant" name="N" data="1"/>'
            '<module class="BlockMatching" name="M" block_radius="3" search_window_radius="5" '
            'metric="1"/>'
            '<connection source="F.OUTPUT" target="M.INPUT" delay="0"/>'
            '<connection source="F.OUTPUT" target="M.INPUT-LAST" delay="1"/>'
            '<connection source="P.OUTPUT" target="M.POINTS" delay="0"/>'
            '<connection source="N.OUTPUT" target="M.NO-OF-POINTS" delay="0"/>')
    with load_sequence(tmp_path, frames, body) as net:
        net.run(ticks=2)
        assert np.array_equal(net.output("M.FLOW"), [[30, 30, 2, 0], [0, 0, 0, 0]])
        assert net.output("M.FLOW-SIZE")[0] == 1


def pair_table(points, motions):
    """Rows (x0, y0, x1, y1): each point and where it moved to."""
    points = np.asarray(points, np.float32)
    return np.hstack([points, points + np.asarray(motions, np.float32)])


def direction(tmp_path, table, ticks=1, **params):
    from vision_models import run
    attrs = {k: str(v) for k, v in params.items()}
    with run(tmp_path, "DirectionDetector", {"INPUT": table}, ticks=ticks, **attrs) as net:
        return {n: net.output(f"M.{n}").copy() for n in (
            "MOTION-VECTOR", "MOTION-DIRECTION", "LOOMING", "LEFT-FIELD-MOTION",
            "RIGHT-FIELD-MOTION", "MOTION-VECTOR-DRAW")}


def test_direction_detector_global_motion(tmp_path):
    points = np.array([[10, 10], [30, 10], [10, 30], [30, 30]])
    out = direction(tmp_path, pair_table(points, [[2, -1]] * 4))
    assert np.allclose(out["MOTION-VECTOR"], [8, -4])              # the sum over the rows
    assert out["MOTION-DIRECTION"].tolist() == [0, 1, 0, 0]        # mostly to the right
    assert np.isclose(out["LOOMING"][0], 0)
    assert np.isclose(out["LEFT-FIELD-MOTION"][0], 2 * np.sqrt(5))
    assert np.isclose(out["RIGHT-FIELD-MOTION"][0], 2 * np.sqrt(5))
    assert np.allclose(out["MOTION-VECTOR-DRAW"], [0.5, 0.5, 8.5, -3.5])


def test_direction_detector_keeps_0_7_of_the_previous_vector(tmp_path):
    out = direction(tmp_path, pair_table([[10, 10]], [[0, 3]]), ticks=3)
    assert np.allclose(out["MOTION-VECTOR"], [0, 3 * (1 + 0.7 + 0.49)])
    assert out["MOTION-DIRECTION"].tolist() == [0, 0, 0, 1]        # down (y points down)


def test_direction_detector_looming_and_fields(tmp_path):
    points = np.array([[10, 20], [30, 20], [20, 10], [20, 30]])
    out = direction(tmp_path, pair_table(points, [[-1, 0], [1, 0], [0, -1], [0, 1]]))
    assert np.allclose(out["MOTION-VECTOR"], 0)
    assert out["MOTION-DIRECTION"].tolist() == [0, 0, 0, 0]
    assert np.isclose(out["LOOMING"][0], 1)                   # every point moves out by 1
    assert np.isclose(out["LEFT-FIELD-MOTION"][0], 1)
    assert np.isclose(out["RIGHT-FIELD-MOTION"][0], 1)


def test_direction_detector_crop_and_no_of_rows(tmp_path):
    points = np.array([[10, 10], [30, 10], [50, 10]])
    out = direction(tmp_path, pair_table(points, [[1, 0], [40, 0], [2, 0]]), crop=10)
    assert np.allclose(out["MOTION-VECTOR"], [3, 0])
    from vision_models import run
    table = pair_table(points, [[1, 0], [40, 0], [2, 0]])
    with run(tmp_path, "DirectionDetector", {"INPUT": table, "NO-OF-ROWS": np.array([2.0])}) \
            as net:
        assert np.allclose(net.output("M.MOTION-VECTOR"), [41, 0])


def mixture(values, rate, variance, k, t, threshold, truncated=False):
    """The mixture of one pixel, value by value, as StaufferGrimson's description says
    (``truncated``: the match test on the whole part of the distance, Ikaros 2's reading):
    returns the foreground flags and the last weights, means and variances."""
    w, m, v = [1.0] + [0.0] * (k - 1), [values[0]] + [0.0] * (k - 1), [variance] * k
    flags = [0]
    for x in values[1:]:
        rank = [w[i] / v[i] ** 0.5 for i in range(k)]
        distance = [float(np.trunc(x - m[i])) if truncated else x - m[i] for i in range(k)]
        matches = [i for i in range(k) if distance[i] ** 2 <= threshold ** 2 * v[i]]
        chosen = max(matches, key=lambda i: rank[i]) if matches else min(range(k),
                                                                          key=lambda i: rank[i])
        w = [(1 - rate) * wi for wi in w]
        if matches:
            m[chosen] += rate * (x - m[chosen])
            v[chosen] += rate * ((x - m[chosen]) ** 2 - v[chosen])
        else:
            m[chosen], v[chosen] = x, variance
        w[chosen] += rate
        w = [wi / sum(w) for wi in w]
        order = sorted(range(k), key=lambda i: -w[i] / v[i] ** 0.5)
        background, total = set(), 0.0
        for i in order:
            if total > t:
                break
            background.add(i)
            total += w[i]
        flags.append(0 if matches and chosen in background else 1)
    return flags, w, m, v


def test_stauffer_grimson_with_ikaros3_parameters_and_model_outputs(tmp_path):
    """An Ikaros 3 file: learning_rate, max_gaussians and initial_variance (images of
    0..255), and the WEIGHTS, MEANS and VARIANCES of each pixel."""
    rng = np.random.default_rng(6)
    frames = (rng.normal(100, 4, (12, 2, 3)) + np.arange(12)[:, None, None] * 3).astype(
        np.float32)
    frames[6:9, 1, 2] = 220                            # something passes pixel (1, 2)
    body = ('<module class="StaufferGrimson" name="M" learning_rate="0.05" max_gaussians="3" '
            'initial_variance="64"/>')
    names = ("OUTPUT", "WEIGHTS", "MEANS", "VARIANCES")
    out = run_sequence(tmp_path, frames, body, *names, dialect=3)
    for r in range(2):
        for c in range(3):
            flags, w, m, v = mixture(frames[:, r, c].astype(np.float64), 0.05, 64.0, 3, 0.8,
                                     2.5)
            assert [o[0][r, c] for o in out] == flags, (r, c)
            last = out[-1]
            assert last[1].shape == (2, 3, 3)
            assert np.allclose(last[1][r, c], w, atol=1e-5)
            assert np.allclose(last[2][r, c], m, rtol=1e-5)
            assert np.allclose(last[3][r, c], v, rtol=1e-4)
    assert [o[0][1, 2] for o in out][6:9] == [1, 1, 1]


def test_stauffer_grimson_ikaros2_matches_on_the_whole_part_of_the_distance(tmp_path):
    """An Ikaros 2 file: a value matches a Gaussian while the whole part of its distance is
    within threshold standard deviations, so a background at 0.5 takes in values up to
    0.9 away (1.4, -0.3) where the exact test takes in none; a jump of 2 is foreground
    while its own Gaussian has little weight."""
    values = np.array([0.5, 1.4, -0.3, 0.9, 2.5, 2.6, 0.5, -0.6, 3.2, 2.4, 2.45, 0.2],
                      np.float32)
    frames = np.tile(values[:, None, None], (1, 1, 2))
    frames[:, 0, 1] += 10                           # the same steps around another level
    out = run_sequence(tmp_path, frames, '<module class="StaufferGrimson" name="M" '
                       'alpha="0.05"/>', "OUTPUT")
    for c in range(2):
        flags, *_ = mixture(frames[:, 0, c].astype(np.float64), 0.05, 0.02 ** 2, 5, 0.8, 2.5,
                            truncated=True)
        assert [int(o[0][0, c]) for o in out] == flags
    assert [int(o[0][0, 0]) for o in out] == [0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0, 0]
    exact = run_sequence(tmp_path, frames, '<module class="StaufferGrimson" name="M" '
                         'alpha="0.05" match="exact"/>', "OUTPUT")
    assert [int(o[0][0, 0]) for o in exact][1:4] == [1, 1, 1]
