"""PyramidalLucasKanadeTracker: a seeded template is followed through images moved by known
offsets (sub-pixel ones included), is lost when the image changes, and takes a new seed
only when it agrees with the track (or the track is lost)."""
import numpy as np
import pytest

from sequences import load_sequence
from textures import texture, waves

cv2 = pytest.importorskip("cv2")

RESULT_SIZE = 8


def seed_result(found, points=0, template=0):
    result = np.zeros(RESULT_SIZE)
    result[:3] = (found, template, points)
    return result


def grid(n=8, x0=80.0, y0=60.0, step=20.0):
    """n x n points in a square of the frame, one row (x, y) each."""
    ys, xs = np.mgrid[0:n, 0:n]
    return np.column_stack([x0 + step * xs.ravel(), y0 + step * ys.ravel()])


def run_tracker(tmp_path, frames, points, results, homographies=None, reference=None,
                **params):
    """Run the tracker on the frames; on tick k it gets SEED_RESULT results[k],
    SEED_HOMOGRAPHY homographies[k] (default: the identity), the keypoints ``points`` (rows
    x, y; or a list of such, one per tick), the template points ``reference`` (default: the
    first keypoints) and inliers pairing row i with row i. Returns per tick (TRANSFORM,
    RESULT, REFERENCE_POINTS, CURRENT_POINTS)."""
    n = len(frames)
    points = np.asarray(points, float)
    per_tick = points if points.ndim == 3 else np.repeat(points[None], n, axis=0)
    reference = per_tick[0] if reference is None else reference
    homographies = [np.eye(3)] * n if homographies is None else homographies
    pairs = np.column_stack([np.arange(len(reference))] * 2)
    for name, sequence in (("Result", results), ("Seed", homographies), ("Points", per_tick)):
        np.save(tmp_path / f"{name}.npy", np.asarray(sequence, np.float32))
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = f'''
<module class="Frames" name="Result" file="{tmp_path}/Result.npy"/>
<module class="Frames" name="Seed" file="{tmp_path}/Seed.npy"/>
<module class="Frames" name="Points" file="{tmp_path}/Points.npy"/>
<module class="Constant" name="Reference" data="{";".join(f"{x} {y}" for x, y in reference)}"/>
<module class="Constant" name="Pairs" data="{";".join(f"{a} {b}" for a, b in pairs)}"/>
<module class="Constant" name="Ranges" data="0 {len(reference)}"/>
<module class="PyramidalLucasKanadeTracker" name="M" {attrs}/>
<connection source="F.OUTPUT" target="M.IMAGE" delay="0"/>
<connection source="Points.OUTPUT" target="M.KEYPOINTS" delay="0"/>
<connection source="Reference.OUTPUT" target="M.TEMPLATE_KEYPOINTS" delay="0"/>
<connection source="Ranges.OUTPUT" target="M.TEMPLATE_RANGES" delay="0"/>
<connection source="Seed.OUTPUT" target="M.SEED_HOMOGRAPHY" delay="0"/>
<connection source="Result.OUTPUT" target="M.SEED_RESULT" delay="0"/>
<connection source="Pairs.OUTPUT" target="M.SEED_INLIERS" delay="0"/>
'''
    out = []
    with load_sequence(tmp_path, frames, body) as net:
        for _ in range(n):
            net.step()
            out.append([net.output(f"M.{name}").copy() for name in
                        ("TRANSFORM", "RESULT", "REFERENCE_POINTS", "CURRENT_POINTS")])
    return out


def test_follows_a_texture_moved_by_known_sub_pixel_offsets(tmp_path):
    offsets = [(0, 0), (1.5, -0.75), (3.25, -1.5), (5.0, -2.0), (6.5, -1.25)]
    frames = [waves(dx=dx, dy=dy) for dx, dy in offsets]
    points = grid()
    results = [seed_result(1, len(points))] + [seed_result(0)] * (len(frames) - 1)
    out = run_tracker(tmp_path, frames, points, results)
    for (dx, dy), (transform, result, reference, current) in zip(offsets, out):
        assert result[0] == 1 and result[1] == 0
        assert np.allclose(reference, points, atol=1e-4)
        motion = current - reference                       # each point within 0.3 pixel,
        assert np.allclose(motion, [dx, dy], atol=0.3), (dx, dy)     # their median 0.05
        assert np.allclose(np.median(motion, axis=0), [dx, dy], atol=0.05), (dx, dy)
        transform = transform / transform[2, 2]
        assert np.allclose(transform[:2, 2], [dx, dy], atol=0.1)
        assert np.allclose(transform[:2, :2], np.eye(2), atol=0.005)
        assert np.allclose(transform[2, :2], 0, atol=1e-4)
    assert out[-1][1][2] >= 0.9 * len(points)            # most points kept
    assert out[-1][1][4] <= 0.2                          # forward-backward error, pixels


def test_the_transform_maps_template_points_to_the_image(tmp_path):
    # the template was learned where the image is now moved by (10, 4); seeded with that
    frames = [waves(dx=10, dy=4), waves(dx=12, dy=5)]
    points = grid() + [10, 4]
    seed = np.array([[1, 0, 10], [0, 1, 4], [0, 0, 1]], float)
    results = [seed_result(1, len(points)), seed_result(0)]
    out = run_tracker(tmp_path, frames, points, results, homographies=[seed, seed],
                      reference=grid())
    transform, result, reference, current = out[1]
    assert np.allclose(reference, grid(), atol=1e-4)
    assert np.allclose(np.median(current - reference, axis=0), [12, 5], atol=0.05)
    assert np.allclose(transform / transform[2, 2], [[1, 0, 12], [0, 1, 5], [0, 0, 1]],
                       atol=0.1)


def test_a_new_image_loses_the_target(tmp_path):
    frames = [texture(seed=1), texture(seed=2)]
    points = grid()
    out = run_tracker(tmp_path, frames, points, [seed_result(1, len(points)), seed_result(0)])
    assert out[0][1][0] == 1
    assert out[1][1][0] == 0 and out[1][1][1] == -1
    assert out[1][2].shape == (0, 2) and out[1][3].shape == (0, 2)


def test_a_seed_far_from_a_good_track_is_refused_and_a_near_one_taken(tmp_path):
    # the image stands still; from tick 1 on the detector claims the template moved 40
    # pixels right (its keypoints and homography say so)
    frames = [waves()] * 3
    points = [grid(), grid() + [40, 0], grid() + [40, 0]]
    far = np.array([[1, 0, 40], [0, 1, 0], [0, 0, 1]], float)
    results = [seed_result(1, 64)] * 3
    homographies = [np.eye(3), far, far]
    out = run_tracker(tmp_path, frames, points, results, homographies,
                      max_reseed_displacement="20")
    for transform, result, reference, current in out[1:]:     # 40 > 20: refused
        assert np.allclose(transform / transform[2, 2], np.eye(3), atol=0.02)
        assert np.allclose(current, grid(), atol=0.05) and result[0] == 1
    out = run_tracker(tmp_path, frames, points, results, homographies,
                      max_reseed_displacement="50")
    assert np.allclose(out[1][0], far) and np.allclose(out[1][3], grid() + [40, 0])


def test_too_few_seed_points_seed_nothing(tmp_path):
    points = grid(2)                                              # 4 < min_points 6
    out = run_tracker(tmp_path, [waves()], points, [seed_result(1, 4)])
    assert out[0][1][0] == 0 and out[0][3].shape == (0, 2)
