"""Tests of the tracking modules: SpatialClustering, MarkerTracker, CalibrateCameraPosition
and DTracker, against the synthetic camera's truth and images with known answers."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body

from sequences import run_sequence
from vision_models import run

cv2 = pytest.importorskip("cv2")


def disc_map(rows, cols, discs):
    image = np.zeros((rows, cols), np.float32)
    for x, y, r, value in discs:
        cv2.circle(image, (x, y), r, value, -1)
    return image


def centre(x, y, rows, cols):
    """The position SpatialClustering gives the pixel (x, y): column / cols and row / rows,
    as Ikaros 2's golden outputs (column 3 of 4 is 0.75)."""
    return [x / cols, y / rows]


def raster_clusters(image, threshold, radius, limit):
    """The clustering, written out: pixels above threshold in raster order join the nearest
    cluster whose running centroid is within ``radius`` pixels, or start one; when there are
    ``limit`` clusters already, the last one starts anew (Ikaros 2's golden outputs)."""
    clusters, sums = [], []                           # lists of (col, row); their sums
    for r in range(image.shape[0]):
        for c in range(image.shape[1]):
            if image[r, c] <= threshold:
                continue
            near = [(np.hypot(sc / len(k) - c, sr / len(k) - r), i)
                    for i, (k, (sc, sr)) in enumerate(zip(clusters, sums))]
            near = [d_i for d_i in near if d_i[0] <= radius]
            if near:
                i = min(near)[1]
                clusters[i].append((c, r))
                sums[i] = (sums[i][0] + c, sums[i][1] + r)
            elif len(clusters) < limit:
                clusters.append([(c, r)])
                sums.append((c, r))
            else:
                clusters[-1], sums[-1] = [(c, r)], (c, r)
    return clusters


def test_clusters_by_raster_order_and_area_of_the_image(tmp_path):
    image = disc_map(60, 80, [(15, 20, 6, 1.0), (60, 40, 4, 1.0), (40, 10, 1, 0.5)])
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, no_of_clusters="3",
             cluster_radius="0.1", min_cluster_area="0.005", positions="current") as net:
        out, conf = net.output("M.OUTPUT"), net.output("M.CONFIDENCE")
    # r = 0.1 * 80 = 8 pixels; kept when more than 0.005 * 4800 = 24 pixels
    clusters = raster_clusters(image, 0.1, 8.0, 3)
    assert [len(k) for k in clusters] == [5, 113, 49]   # speck first: it is highest
    assert out.shape == (3, 2) and conf.shape == (3,)
    for row, k in zip(out, clusters[1:]):
        c, r = np.mean(k, axis=0)
        assert np.allclose(row, [c / 80, r / 60], atol=1e-6)
    assert np.allclose(out[0], centre(15, 20, 60, 80), atol=1e-6)   # the disc's centre
    area = 2 * np.pi * 8 ** 2
    assert np.allclose(conf, [113 / area, 49 / area, 0], atol=1e-6)
    assert np.array_equal(out[2], [0, 0])             # the speck is too small


def test_running_centroid_and_capped_confidence(tmp_path):
    # a row of pixels 0..4 and 8, radius 0.2 * 10 = 2 pixels. The centroid runs 0, 0.5, 1:
    # pixel 3 is 2 from it and joins (centroid 1.5); pixel 4 is 2.5 away and starts a
    # second cluster, pixel 8 (4 from that one) a third
    image = np.zeros((3, 10), np.float32)
    image[1, 0:5] = 1
    image[1, 8] = 1
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, no_of_clusters="3",
             cluster_radius="0.2", min_cluster_area="0", positions="current") as net:
        out, conf = net.output("M.OUTPUT"), net.output("M.CONFIDENCE")
    assert np.allclose(out, [[1.5 / 10, 1 / 3], [4 / 10, 1 / 3], [8 / 10, 1 / 3]], atol=1e-6)
    assert np.allclose(conf, np.array([4, 1, 1]) / (2 * np.pi * 4), atol=1e-6)
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, no_of_clusters="3",
             cluster_radius="0", min_cluster_area="0", positions="current") as net:
        # 1 / 0 pixels: capped; the fourth and later isolated pixels restart the last
        assert np.array_equal(net.output("M.CONFIDENCE"), [1, 1, 1])
        assert np.allclose(net.output("M.OUTPUT")[:, 0], [0.0, 0.1, 0.8])


@pytest.mark.parametrize("discs, fraction, limit", [
    ([(60, 60, 50, 1.0)], 0.3, 1), ([(60, 60, 50, 1.0)], 0.1, 3),
    ([(40, 40, 22, 1.0), (95, 45, 22, 1.0), (135, 70, 18, 1.0)], 0.15, 3)])
def test_thousands_of_pixels_cluster_as_pixel_by_pixel(tmp_path, discs, fraction, limit):
    # discs wider than the radius: centroids that drift, pixels that start clusters anew,
    # long runs that join; the module settles many pixels at a time
    image = disc_map(120, 200, discs)
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, no_of_clusters=str(limit),
             cluster_radius=str(fraction), min_cluster_area="0", positions="current") as net:
        out, conf = net.output("M.OUTPUT"), net.output("M.CONFIDENCE")
    radius = fraction * 200
    clusters = raster_clusters(image, 0.1, radius, limit)
    assert len(clusters) == limit
    expected = [np.mean(k, axis=0) / (200, 120) for k in clusters]
    assert np.allclose(out, expected, atol=1e-6)
    assert np.allclose(conf, [min(len(k) / (2 * np.pi * radius ** 2), 1) for k in clusters],
                       atol=1e-6)


def test_threshold_is_strict(tmp_path):
    image = disc_map(40, 40, [(20, 20, 5, 0.1)])
    image[10, 30] = 1.0
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, threshold="0.1",
             min_cluster_area="0", positions="current") as net:
        assert np.allclose(net.output("M.OUTPUT")[0], centre(30, 10, 40, 40))


def test_unused_rows_have_confidence_0_every_tick(tmp_path):
    frames = np.array([disc_map(30, 40, [(10, 10, 3, 1.0), (30, 20, 3, 1.0)]),
                       disc_map(30, 40, [(10, 10, 3, 1.0)])])
    out = run_sequence(tmp_path, frames, '<module class="SpatialClustering" name="M" '
                       'no_of_clusters="2" min_cluster_area="0.001"/>', "CONFIDENCE")
    assert (out[0][0] > 0).all()
    assert out[1][0][0] > 0 and out[1][0][1] == 0


def test_clusters_keep_their_rows_while_they_move(tmp_path):
    frames = []
    for k in range(5):           # A moves right, B moves left; they swap sides
        frames.append(disc_map(50, 100, [(20 + 15 * k, 15, 4, 1.0),
                                         (80 - 15 * k, 35, 5, 1.0)]))
    out = run_sequence(tmp_path, np.array(frames), '<module class="SpatialClustering" '
                       'name="M" no_of_clusters="2" cluster_radius="0.08" '
                       'min_cluster_area="0.005" positions="current"/>', "OUTPUT")
    first = out[0][0]
    a_row = int(np.argmin(first[:, 0]))
    for k, (positions,) in enumerate(out):
        assert np.allclose(positions[a_row], centre(20 + 15 * k, 15, 50, 100), atol=1e-6)
        assert np.allclose(positions[1 - a_row], centre(80 - 15 * k, 35, 50, 100), atol=1e-6)


def test_sorting_orders_by_confidence(tmp_path):
    image = disc_map(40, 80, [(10, 20, 3, 1.0), (60, 20, 6, 1.0)])
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, no_of_clusters="2",
             sorting="yes", min_cluster_area="0.001", positions="current") as net:
        assert np.allclose(net.output("M.OUTPUT"), [centre(60, 20, 40, 80),
                                                   centre(10, 20, 40, 80)], atol=1e-6)


def test_synthetic_camera_discs_are_found_a_tick_late_as_ikaros2(tmp_path):
    net = load_body(tmp_path, '''
        <module class="SyntheticCamera" name="C" blobs="1" size_x="320" size_y="240"/>
        <module class="SpatialClustering" name="S" threshold="0.8" cluster_radius="0.05"
                min_cluster_area="0.001"/>
        <module class="SpatialClustering" name="Now" threshold="0.8" cluster_radius="0.05"
                min_cluster_area="0.001" positions="current"/>
        <connection source="C.RED" target="S.INPUT" delay="0"/>
        <connection source="C.RED" target="Now.INPUT" delay="0"/>''')
    with net:
        before = np.zeros(2)
        for _ in range(4):
            net.step()
            # the camera's positions are pixel centres; the clusters' pixel corners
            truth = net.output("C.POSITIONS")[0] - 0.5 / np.array([320, 240])
            assert np.allclose(net.output("Now.OUTPUT")[0], truth, atol=1e-6)
            assert np.allclose(net.output("S.OUTPUT")[0], before, atol=1e-6)
            assert net.output("S.CONFIDENCE")[0] == net.output("Now.CONFIDENCE")[0] > 0
            before = truth


CALIBRATION = "640 480 320 240 600 600 0 0 0 0"


def markers(tmp_path, ids="3 7", extra=""):
    return load_body(tmp_path, f'''
        <module class="SyntheticCamera" name="C" blobs="0" markers="{ids}"/>
        <module class="MarkerTracker" name="M" calibration="{CALIBRATION}" {extra}/>
        <connection source="C.OUTPUT" target="M.INPUT" delay="0"/>''')


def test_marker_ids_corners_and_positions(tmp_path):
    with markers(tmp_path, "7 3 12") as net:
        net.step()
        assert net.output("M.MARKER_COUNT")[0] == 3
        table = net.output("M.MARKERS")
        assert table.shape == (10, 28)
        assert table[:3, 0].tolist() == [3, 7, 12] and table[3:].sum() == 0
        truth = dict(zip([7, 3, 12], net.output("C.MARKER_CORNERS")))
        pixel = np.tile([1 / 640, 1 / 480], 4)
        for row in table[:3]:
            assert np.all(np.abs(row[4:12] - truth[int(row[0])]) < 0.75 * pixel)
            assert np.allclose(row[2:4], truth[int(row[0])].reshape(4, 2).mean(axis=0),
                               atol=0.5 / 640)
        assert np.array_equal(net.output("M.OBJECT_ID").ravel()[:3], [3, 7, 12])
        assert np.array_equal(net.output("M.EDGES")[:3], table[:3, 4:12])
        assert np.array_equal(net.output("M.CONFIDENCE").ravel(), [1, 1, 1] + [0] * 7)


def test_marker_pose_from_its_size_and_the_calibration(tmp_path):
    with markers(tmp_path, "3") as net:
        net.step()
        corners = net.output("C.MARKER_CORNERS")[0].reshape(4, 2) * [640, 480] - 0.5
        side = corners[1, 0] - corners[0, 0]               # 80 pixels
        distance = 600 * 45 / side
        u, v = corners.mean(axis=0)
        pose = net.output("M.MATRIX")[0].reshape(4, 4)
        forward, left, up = pose[:3, 3]                    # the Ikaros frame
        assert abs(forward - distance) < 0.01 * distance
        assert abs(left - (-(u - 320) * distance / 600)) < 1.0
        assert abs(up - (-(v - 240) * distance / 600)) < 1.0
        assert pose[0, 2] < -0.9                           # the marker faces the camera
        assert np.array_equal(net.output("M.MODEL_VIEW"), pose)
        assert np.array_equal(net.output("M.PROJECTION"),
                              [[600, 0, 320, 0], [0, 600, 240, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def test_marker_pose_in_the_camera_frame(tmp_path):
    with markers(tmp_path, "3", 'coordinate_system="artoolkit"') as net:
        net.step()
        x, y, z = net.output("M.MATRIX")[0].reshape(4, 4)[:3, 3]
        assert 300 < z < 380 and x < 0 and y > 0               # left of and below the centre


def test_no_markers_and_bad_calibration(tmp_path):
    with markers(tmp_path, "") as net:
        net.step()
        assert net.output("M.MARKER_COUNT")[0] == 0
        assert np.array_equal(net.output("M.MODEL_VIEW"), np.eye(4))
    with pytest.raises(ModelError, match="calibration needs at least"):
        run(tmp_path, "MarkerTracker", {"INPUT": np.zeros((40, 40))}, calibration="1 2")


def test_camera_position_from_a_known_marker(tmp_path):
    with markers(tmp_path, "3 7") as net:
        net.step()
        seen = net.output("M.MATRIX")[1].reshape(4, 4).astype(np.float64)
    world = np.array([[1, 0, 0, 500], [0, 1, 0, 100], [0, 0, 1, 0], [0, 0, 0, 1]], float)
    table = np.zeros((10, 28), np.float32)
    table[0, 0], table[0, 1], table[0, 12:] = 7, 1, seen.ravel()
    with run(tmp_path, "CalibrateCameraPosition", {"INPUT": table},
             marker_number="7") as net:
        assert np.allclose(net.output("M.CAMERA"), world @ np.linalg.inv(seen), atol=1e-3)
        assert net.output("M.FOUND")[0] == 1
        assert any("camera position from marker 7" in m for *_, m in net.log)
    with run(tmp_path, "CalibrateCameraPosition", {"INPUT": table}) as net:   # id 1218
        assert net.output("M.FOUND")[0] == 0 and np.array_equal(net.output("M.CAMERA"),
                                                                np.eye(4))


def textured_square_frames(steps, dx, dy, rows=120, cols=160, side=30):
    rng = np.random.default_rng(5)
    patch = cv2.resize(rng.random((6, 6)).astype(np.float32), (side, side),
                       interpolation=cv2.INTER_NEAREST)
    frames, truth = [], []
    for k in range(steps):
        frame = np.full((rows, cols), 0.5, np.float32)
        x, y = 40 + dx * k, 40 + dy * k
        frame[y:y + side, x:x + side] = patch
        frames.append(frame)
        truth.append(((x + side / 2) / cols, (y + side / 2) / rows))
    return np.array(frames), np.array(truth)


def test_dtracker_follows_a_moving_square(tmp_path):
    frames, truth = textured_square_frames(12, 3, 2)
    out = run_sequence(tmp_path, frames, '<module class="DTracker" name="M" '
                       'box="0.25 0.333333 0.4375 0.583333"/>', "TRACKER_POSITION",
                       "TRACKING", "TRACKER_BOUNDS")
    for k, (position, tracking, bounds) in enumerate(out):
        assert tracking[0] == 1
        assert np.all(np.abs(position - truth[k]) < [4 / 160, 4 / 120]), k
        corners = bounds.reshape(4, 2)
        assert np.allclose(corners.mean(axis=0), position, atol=1e-6)


def test_dtracker_loses_an_object_that_vanishes(tmp_path):
    frames, _ = textured_square_frames(4, 2, 0)
    frames[3] = 0.5                                          # the square is gone
    out = run_sequence(tmp_path, frames, '<module class="DTracker" name="M" '
                       'box="0.25 0.333333 0.4375 0.583333"/>', "TRACKING", "TRACKER_POSITION")
    assert [t[0] for t, _ in out] == [1, 1, 1, 0]
    assert np.array_equal(out[3][1], out[2][1])              # the box stays


def test_dtracker_starts_at_a_box_input(tmp_path):
    frames, truth = textured_square_frames(6, 2, 3)
    body = ('<module class="Constant" name="B" data="0.25 0.333333 0.4375 0.583333"/>'
            '<module class="DTracker" name="M"/>'
            '<connection source="F.OUTPUT" target="M.INPUT" delay="0"/>'
            '<connection source="B.OUTPUT" target="M.BOX" delay="0"/>')
    from sequences import load_sequence
    with load_sequence(tmp_path, frames, body) as net:
        for k in range(6):
            net.step()
            assert np.all(np.abs(net.output("M.TRACKER_POSITION") - truth[k]) <
                          [2 / 160, 2 / 120]), k


def test_a_large_cluster_radius_counts_in_floats(tmp_path):
    image = disc_map(60, 600, [(300, 30, 20, 1.0)])          # radius 0.5: a 601-pixel square
    with run(tmp_path, "SpatialClustering", {"INPUT": image}, cluster_radius="0.5",
             min_cluster_area="0.01", positions="current") as net:
        assert np.allclose(net.output("M.OUTPUT")[0], centre(300, 30, 60, 600), atol=1e-6)


def test_markers_with_a_fixed_threshold(tmp_path):
    with markers(tmp_path, "3 7", 'threshold="128"') as net:
        net.step()
        assert net.output("M.OBJECT_ID").ravel()[:2].tolist() == [3, 7]
