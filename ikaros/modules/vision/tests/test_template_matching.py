"""The template-matching classes of Ikaros 3 on OpenCV: RobustTransformEstimator recovers a
known homography among outliers, TemplateFeatureBank learns and forgets templates,
FeatureRegionFilter, FeatureMatcher and ORBFeatureExtractor pass on what they should,
TemplatePolygonTransform and FeaturePointBoxes give drawable positions, the controller
chooses between detection and tracking, and the whole chain finds a moved texture."""
import numpy as np
import pytest

from ikaros.errors import ModelError

from sequences import load_sequence
from textures import moved, texture
from vision_models import run

cv2 = pytest.importorskip("cv2")

WIDTH, HEIGHT = 320, 240
H_TRUE = np.array([[0.95, -0.12, 30.0], [0.10, 1.05, -12.0], [2e-4, -1e-4, 1.0]])
OUTLINE = np.array([80, 60, 240, 60, 240, 180, 80, 180], float)     # the template's corners


def mapped(h, points):
    """Points (rows x, y) through a homography, written out."""
    p = np.column_stack([points, np.ones(len(points))]) @ np.asarray(h).T
    return p[:, :2] / p[:, 2:]


def shoelace(corners):
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * abs(np.sum(x * np.roll(y, -1) - y * np.roll(x, -1)))


def scene(n=40, outliers=10, seed=4):
    """Template points in the outline, the image points the true homography gives them,
    and ``outliers`` matches whose image points are elsewhere (the last rows)."""
    rng = np.random.default_rng(seed)
    template = np.column_stack([rng.uniform(85, 235, n), rng.uniform(65, 175, n)])
    image = mapped(H_TRUE, template)
    image[n - outliers:] = np.column_stack([rng.uniform(0, WIDTH, outliers),
                                            rng.uniform(0, HEIGHT, outliers)])
    matches = np.column_stack([np.zeros(n), np.arange(n), np.arange(n), np.full(n, 0.9)])
    return template, image, matches


def estimate(tmp_path, template, image, matches, ranges=None, corners=None, **params):
    inputs = {"KEYPOINTS": image, "TEMPLATE_KEYPOINTS": template,
              "TEMPLATE_RANGES": [[0, len(template)]] if ranges is None else ranges,
              "TEMPLATE_CORNERS": [OUTLINE] if corners is None else corners,
              "CORRESPONDENCES": matches}
    with run(tmp_path, "RobustTransformEstimator", inputs, **params) as net:
        return [net.output(f"M.{n}").copy() for n in ("HOMOGRAPHY", "INLIERS", "RESULT")]


# --- RobustTransformEstimator -------------------------------------------------------------

def test_recovers_a_known_homography_among_outliers(tmp_path):
    template, image, matches = scene()
    h, inliers, result = estimate(tmp_path, template, image, matches)
    assert np.allclose(h / h[2, 2], H_TRUE, rtol=1e-3, atol=1e-5)
    assert sorted(inliers[:, 0]) == list(range(30)) and np.array_equal(inliers[:, 0],
                                                                       inliers[:, 1])
    area = shoelace(mapped(H_TRUE, OUTLINE.reshape(4, 2))) / (WIDTH * HEIGHT)
    hull = cv2.convexHull(template[:30].astype(np.float32)).reshape(-1, 2)
    coverage = shoelace(hull) / shoelace(OUTLINE.reshape(4, 2))
    assert result[:4].tolist() == [1, 0, 30, 0.75]
    assert result[4] < 1e-3 and result[5] == pytest.approx(0.9)
    assert result[6] == pytest.approx(area, rel=1e-4)
    assert result[7] == pytest.approx(coverage, rel=1e-4)


@pytest.mark.parametrize("params", [{"min_inliers": "31"}, {"min_inlier_ratio": "0.8"},
                                    {"min_mean_match_score": "0.95"},
                                    {"max_area_fraction": "0.2"},
                                    {"min_area_fraction": "0.5"},
                                    {"min_source_coverage": "0.99"}])
def test_a_fit_that_misses_a_criterion_is_not_found(tmp_path, params):
    template, image, matches = scene()
    h, inliers, result = estimate(tmp_path, template, image, matches, **params)
    assert np.array_equal(h, np.eye(3)) and inliers.shape == (0, 2)
    assert result.tolist() == [0, -1, 0, 0, 0, 0, 0, 0]


def test_the_template_with_most_inliers_wins(tmp_path):
    template, image, matches = scene(n=40, outliers=10)
    # template 1: the same points, but only 20 of them fit (20 outliers)
    template2, image2, matches2 = scene(n=40, outliers=20, seed=5)
    matches2[:, 0] = 1
    matches2[:, 1] += 40
    matches2[:, 2] += 40
    h, inliers, result = estimate(
        tmp_path, np.vstack([template, template2]), np.vstack([image, image2]),
        np.vstack([matches2, matches]), ranges=[[0, 40], [40, 40]],
        corners=[OUTLINE, OUTLINE])
    assert result[:3].tolist() == [1, 0, 30]


def test_matches_of_other_templates_or_out_of_range_are_left_out(tmp_path):
    template, image, matches = scene(n=12, outliers=0)
    bad = np.array([[0, 99, 0, 1.0], [0, 0, 99, 1.0], [1, 0, 0, 1.0]])
    h, inliers, result = estimate(tmp_path, template, image, np.vstack([matches, bad]))
    assert result[:3].tolist() == [1, 0, 12]
    assert result[3] == 1.0                      # the bad rows are not counted as matches


# --- TemplateFeatureBank ------------------------------------------------------------------

BANK = '''
<module class="Frames" name="Points" file="{d}/points.npy"/>
<module class="Frames" name="Descriptors" file="{d}/descriptors.npy"/>
<module class="Frames" name="Scores" file="{d}/scores.npy"/>
<module class="Frames" name="Learn" file="{d}/learn.npy"/>
<module class="Frames" name="Clear" file="{d}/clear.npy"/>
<module class="TemplateFeatureBank" name="M" {attrs}/>
<connection source="Points.OUTPUT" target="M.KEYPOINTS" delay="0"/>
<connection source="Descriptors.OUTPUT" target="M.DESCRIPTORS" delay="0"/>
<connection source="Scores.OUTPUT" target="M.SCORES" delay="0"/>
<connection source="Learn.OUTPUT" target="M.LEARN" delay="0"/>
<connection source="Clear.OUTPUT" target="M.CLEAR" delay="0"/>
'''
BANK_OUTPUTS = ("TEMPLATE_KEYPOINTS", "TEMPLATE_DESCRIPTORS", "TEMPLATE_SCORES",
                "TEMPLATE_RANGES", "TEMPLATE_CORNERS")


def run_bank(tmp_path, points, learn, clear=None, **params):
    """Run a bank for len(learn) ticks on per-tick points (descriptor of a point: 4 values
    x, y, x + y, 7; score: x); return per tick the outputs as a dict."""
    points = np.asarray(points, np.float32)
    n = len(learn)
    descriptors = np.concatenate([points, points.sum(-1, keepdims=True),
                                  np.full(points.shape[:-1] + (1,), 7.0)], axis=-1)
    sequences = {"points": points, "descriptors": descriptors, "scores": points[..., 0],
                 "learn": np.reshape(learn, (n, 1)),
                 "clear": np.zeros((n, 1)) if clear is None else np.reshape(clear, (n, 1))}
    for name, values in sequences.items():
        np.save(tmp_path / f"{name}.npy", np.asarray(values, np.float32))
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    out = []
    with load_sequence(tmp_path, np.zeros((n, 2, 2)), BANK.format(d=tmp_path, attrs=attrs)) \
            as net:
        for _ in range(n):
            net.step()
            out.append({name: net.output(f"M.{name}").copy() for name in BANK_OUTPUTS})
        log = "\n".join(str(entry) for entry in net.log)
    return out, log


def points_grid(offset=0.0):
    """12 points: 8 inside the central half of the 320 x 240 frame, 4 outside."""
    inside = [(100 + 40 * i + offset, 80 + 40 * j) for i in range(4) for j in range(2)]
    outside = [(10, 10), (300, 10), (10, 230), (300, 230)]
    return np.array(inside + outside, float)


def test_learns_the_points_of_the_central_region_on_a_rising_learn(tmp_path):
    a, b = points_grid(), points_grid(offset=5)
    out, _ = run_bank(tmp_path, [a, a, b, b], learn=[1, 1, 0, 1])
    first = out[0]
    assert np.array_equal(first["TEMPLATE_KEYPOINTS"], a[:8])
    assert np.array_equal(first["TEMPLATE_SCORES"], a[:8, 0])
    assert np.array_equal(first["TEMPLATE_DESCRIPTORS"][:, 2], a[:8].sum(1))
    assert first["TEMPLATE_RANGES"].tolist() == [[0, 8]]
    # the central half: x from 159.5 - 80 to 159.5 + 80, y from 119.5 - 60 to 119.5 + 60
    assert first["TEMPLATE_CORNERS"].tolist() == [[79.5, 59.5, 239.5, 59.5, 239.5, 179.5,
                                                   79.5, 179.5]]
    assert out[1]["TEMPLATE_RANGES"].tolist() == [[0, 8]]        # LEARN held: no new one
    last = out[3]
    assert last["TEMPLATE_RANGES"].tolist() == [[0, 8], [8, 8]]
    assert np.array_equal(last["TEMPLATE_KEYPOINTS"], np.vstack([a[:8], b[:8]]))


def test_the_oldest_template_goes_first_and_clear_forgets_all(tmp_path):
    frames = [points_grid(offset=k) for k in range(4)]
    out, _ = run_bank(tmp_path, frames, learn=[1, 0, 1, 0], clear=[0, 0, 0, 1],
                      max_templates="1")
    assert np.array_equal(out[2]["TEMPLATE_KEYPOINTS"], frames[2][:8])
    assert out[2]["TEMPLATE_RANGES"].tolist() == [[0, 8]]
    assert out[3]["TEMPLATE_RANGES"].shape == (0, 2)
    assert out[3]["TEMPLATE_KEYPOINTS"].shape == (0, 2)


def test_too_few_points_learn_nothing_and_say_so(tmp_path):
    out, log = run_bank(tmp_path, [points_grid()], learn=[1], min_features="9")
    assert out[0]["TEMPLATE_RANGES"].shape == (0, 2)
    assert "at least 9 points" in log and "there were 8" in log


# --- FeatureRegionFilter, FeaturePointBoxes -------------------------------------------------

def test_region_filter_keeps_the_central_points_while_restricted(tmp_path):
    points = points_grid()
    descriptors = np.arange(12 * 3, dtype=float).reshape(12, 3)
    for restrict, kept in ((1, 8), (0, 12)):
        with run(tmp_path, "FeatureRegionFilter", {"KEYPOINTS": points,
                                                   "DESCRIPTORS": descriptors,
                                                   "RESTRICT": [restrict]},
                 descriptor_size="3") as net:
            assert np.array_equal(net.output("M.FILTERED_KEYPOINTS"), points[:kept])
            assert np.array_equal(net.output("M.FILTERED_DESCRIPTORS"), descriptors[:kept])


def test_region_filter_refuses_descriptors_of_another_size(tmp_path):
    with pytest.raises(ModelError, match='descriptor_size="3"'):
        run(tmp_path, "FeatureRegionFilter", {"KEYPOINTS": points_grid(),
                                              "DESCRIPTORS": np.zeros((12, 3)),
                                              "RESTRICT": [1]})


def test_point_boxes_are_squares_around_the_points_in_0_to_1(tmp_path):
    points = np.array([[0, 0], [159.5, 119.5], [300, 17]])
    with run(tmp_path, "FeaturePointBoxes", {"POINTS": points}, box_size="8") as net:
        boxes = net.output("M.BOXES")
    expected = [[(x - 4 + 0.5) / 320, (y - 4 + 0.5) / 240, 8 / 320, 8 / 240]
                for x, y in points]
    assert np.allclose(boxes, expected, atol=1e-7)


# --- FeatureMatcher, ORBFeatureExtractor ----------------------------------------------------

def test_matcher_pairs_each_template_descriptor_with_its_noisy_copy(tmp_path):
    rng = np.random.default_rng(7)
    stored = rng.integers(0, 256, (20, 32))
    order = rng.permutation(20)
    image = stored[order].copy()
    image[:, 0] ^= 1                                   # one bit differs: distance 1
    found = {}
    inputs = {"KEYPOINTS": np.zeros((20, 2)), "DESCRIPTORS": image,
              "TEMPLATE_KEYPOINTS": np.zeros((20, 2)), "TEMPLATE_DESCRIPTORS": stored,
              "TEMPLATE_RANGES": [[0, 12], [12, 8]]}
    with run(tmp_path, "FeatureMatcher", inputs) as net:
        matches = net.output("M.CORRESPONDENCES")
    assert len(matches) == 20
    for template, keypoint, stored_row, score in matches:
        found[int(stored_row)] = int(keypoint)
        assert template == (0 if stored_row < 12 else 1)
        assert score == pytest.approx(1 - 1 / 256)
    assert all(order[found[i]] == i for i in range(20))


def test_orb_extractor_gives_opencvs_points_strongest_first(tmp_path):
    image = texture()
    with run(tmp_path, "ORBFeatureExtractor", {"INPUT": image}, max_features="100") as net:
        points, descriptors = net.output("M.KEYPOINTS"), net.output("M.DESCRIPTORS")
        scores = net.output("M.SCORES")
    orb = cv2.ORB_create(nfeatures=100, fastThreshold=20)
    keypoints, expected = orb.detectAndCompute(
        np.clip(np.rint(image * 255), 0, 255).astype(np.uint8), None)
    order = np.argsort([-k.response for k in keypoints], kind="stable")
    assert len(points) == len(keypoints) > 50
    assert np.allclose(points, [keypoints[i].pt for i in order], atol=1e-4)
    assert np.array_equal(descriptors, expected[order])
    assert np.all(np.diff(scores) <= 0)


def test_orb_extractor_gives_nothing_while_disabled(tmp_path):
    with run(tmp_path, "ORBFeatureExtractor", {"INPUT": texture(), "ENABLE": [0]}) as net:
        assert net.output("M.KEYPOINTS").shape == (0, 2)


# --- TemplatePolygonTransform, TemplateTrackingController ----------------------------------

def polygon(tmp_path, h, result, tracked=None, **params):
    keypoints = np.array([[10, 20], [30, 40], [50, 60]], float)
    inputs = {"HOMOGRAPHY": h, "RESULT": result, "TEMPLATE_CORNERS": [OUTLINE],
              "KEYPOINTS": keypoints, "INLIERS": [[2, 0], [0, 1]]}
    if tracked is not None:
        inputs["TRACKED_POINTS"] = tracked
    with run(tmp_path, "TemplatePolygonTransform", inputs, **params) as net:
        return [net.output(f"M.{n}").copy() for n in ("PATH", "LOCATION",
                                                       "MATCHED_FEATURES")]


def test_polygon_is_the_outline_through_the_homography_in_0_to_1(tmp_path):
    path, location, features = polygon(tmp_path, H_TRUE, [1, 0, 30, 1, 0, 1, 0, 0])
    corners = (mapped(H_TRUE, OUTLINE.reshape(4, 2)) + 0.5) / [320, 240]
    assert np.allclose(path.reshape(5, 2), np.vstack([corners, corners[:1]]), atol=1e-6)
    assert np.allclose(location, list(corners.mean(0)) + [1], atol=1e-6)
    assert np.allclose(features, (np.array([[50, 60], [10, 20]]) + 0.5) / [320, 240])
    _, _, features = polygon(tmp_path, H_TRUE, [1, 0, 30, 1, 0, 1, 0, 0],
                             tracked=[[100, 100]])
    assert np.allclose(features, [[100.5 / 320, 100.5 / 240]])


@pytest.mark.parametrize("result, params", [([0, -1, 0, 0, 0, 0, 0, 0], {}),
                                            ([1, 3, 30, 1, 0, 1, 0, 0], {}),
                                            ([1, 0, 30, 1, 0, 1, 0, 0],
                                             {"max_area_fraction": "0.1"})])
def test_polygon_is_empty_when_nothing_plausible_is_found(tmp_path, result, params):
    path, location, features = polygon(tmp_path, H_TRUE, result, **params)
    assert path.shape == (0, 10) and features.shape == (0, 2) and location[2] == 0


CONTROLLER = '''
<module class="Frames" name="DR" file="{d}/dr.npy"/>
<module class="Frames" name="TR" file="{d}/tr.npy"/>
<module class="Constant" name="DT" data="2 0 0; 0 2 0; 0 0 1"/>
<module class="Constant" name="TT" data="3 0 0; 0 3 0; 0 0 1"/>
<module class="TemplateTrackingController" name="M" detection_interval="3"/>
<connection source="DR.OUTPUT" target="M.DETECTION_RESULT" delay="0"/>
<connection source="TR.OUTPUT" target="M.TRACKING_RESULT" delay="0"/>
<connection source="DT.OUTPUT" target="M.DETECTION_TRANSFORM" delay="0"/>
<connection source="TT.OUTPUT" target="M.TRACKING_TRANSFORM" delay="0"/>
'''


def test_controller_trusts_a_good_track_and_checks_it_every_interval(tmp_path):
    nothing, detected = [0, -1, 0, 0, 0, 0, 0, 0], [1, 2, 20, 1, 0.5, 1, 0.1, 1]
    good, drifting = [1, 2, 20, 1, 0.4, 1, 0.1, 1], [1, 2, 20, 1, 2.0, 1, 0.1, 1]
    dr = [nothing, detected, nothing, nothing, nothing, nothing, detected, nothing]
    tr = [nothing, nothing, good, good, good, good, drifting, nothing]
    np.save(tmp_path / "dr.npy", np.array(dr, np.float32))
    np.save(tmp_path / "tr.npy", np.array(tr, np.float32))
    status, enable, scale, result = [], [], [], []
    with load_sequence(tmp_path, np.zeros((8, 2, 2)), CONTROLLER.format(d=tmp_path)) as net:
        for _ in range(8):
            net.step()
            status.append(int(net.output("M.STATUS")[0]))
            enable.append(int(net.output("M.MATCH_ENABLE")[0]))
            scale.append(float(net.output("M.TRANSFORM")[0, 0]))
            result.append(net.output("M.RESULT").copy())
    assert status == [0, 1, 2, 2, 2, 2, 1, 0]
    assert scale == [1, 2, 3, 3, 3, 3, 2, 1]
    # enabled while not tracking; while tracking, on every third tick since the last
    assert enable == [1, 1, 0, 0, 1, 0, 1, 1]
    assert np.allclose(result[3], good) and np.allclose(result[6], detected)


# --- the whole chain ----------------------------------------------------------------------

CHAIN = '''
<module class="Frames" name="Learn" file="{d}/learn.npy"/>
<module class="Constant" name="Zero" data="0"/>
<module class="ORBFeatureExtractor" name="Features"/>
<module class="TemplateFeatureBank" name="Bank"/>
<module class="FeatureMatcher" name="Matcher"/>
<module class="RobustTransformEstimator" name="Estimator"/>
<module class="TemplatePolygonTransform" name="M"/>
<connection source="F.OUTPUT" target="Features.INPUT" delay="0"/>
<connection source="Features.KEYPOINTS" target="Bank.KEYPOINTS" delay="0"/>
<connection source="Features.DESCRIPTORS" target="Bank.DESCRIPTORS" delay="0"/>
<connection source="Features.SCORES" target="Bank.SCORES" delay="0"/>
<connection source="Learn.OUTPUT" target="Bank.LEARN" delay="0"/>
<connection source="Zero.OUTPUT" target="Bank.CLEAR" delay="0"/>
<connection source="Features.KEYPOINTS" target="Matcher.KEYPOINTS" delay="0"/>
<connection source="Features.DESCRIPTORS" target="Matcher.DESCRIPTORS" delay="0"/>
<connection source="Bank.TEMPLATE_KEYPOINTS" target="Matcher.TEMPLATE_KEYPOINTS" delay="0"/>
<connection source="Bank.TEMPLATE_DESCRIPTORS" target="Matcher.TEMPLATE_DESCRIPTORS" delay="0"/>
<connection source="Bank.TEMPLATE_RANGES" target="Matcher.TEMPLATE_RANGES" delay="0"/>
<connection source="Features.KEYPOINTS" target="Estimator.KEYPOINTS" delay="0"/>
<connection source="Bank.TEMPLATE_KEYPOINTS" target="Estimator.TEMPLATE_KEYPOINTS" delay="0"/>
<connection source="Bank.TEMPLATE_RANGES" target="Estimator.TEMPLATE_RANGES" delay="0"/>
<connection source="Bank.TEMPLATE_CORNERS" target="Estimator.TEMPLATE_CORNERS" delay="0"/>
<connection source="Matcher.CORRESPONDENCES" target="Estimator.CORRESPONDENCES" delay="0"/>
<connection source="Estimator.HOMOGRAPHY" target="M.HOMOGRAPHY" delay="0"/>
<connection source="Estimator.RESULT" target="M.RESULT" delay="0"/>
<connection source="Bank.TEMPLATE_CORNERS" target="M.TEMPLATE_CORNERS" delay="0"/>
<connection source="Features.KEYPOINTS" target="M.KEYPOINTS" delay="0"/>
<connection source="Estimator.INLIERS" target="M.INLIERS" delay="0"/>
'''


def test_the_chain_learns_a_texture_and_finds_it_moved(tmp_path):
    offsets = [(0, 0), (12, 7), (-20, 9), (31, -14)]
    image = texture()
    frames = [moved(image, dx, dy) for dx, dy in offsets] + [texture(seed=9)]
    np.save(tmp_path / "learn.npy", np.array([[1]] + [[0]] * 4, np.float32))
    with load_sequence(tmp_path, frames, CHAIN.format(d=tmp_path)) as net:
        for dx, dy in offsets:
            net.step()
            h = net.output("Estimator.HOMOGRAPHY").astype(float)
            result = net.output("Estimator.RESULT")
            assert result[0] == 1 and result[2] >= 50
            centre = mapped(h, [[159.5, 119.5]])[0]
            assert np.allclose(centre, [159.5 + dx, 119.5 + dy], atol=1.5), (dx, dy)
            location = net.output("M.LOCATION")
            assert np.allclose(location[:2], [(160 + dx) / 320, (120 + dy) / 240],
                               atol=0.01) and location[2] == 1
        net.step()                                       # another texture: not found
        assert net.output("Estimator.RESULT")[0] == 0
        assert net.output("M.LOCATION")[2] == 0
