"""The vision demonstrations in examples/vision give their stated results, headless."""
import os

import numpy as np
import pytest

import ikaros

pytest.importorskip("cv2")

EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                        "examples", "vision")


def load(name):
    return ikaros.load(os.path.join(EXAMPLES, name))


def test_overhead_tracker_follows_each_robot_within_one_pixel():
    with load("overhead_tracker.ikg") as net:
        assert net.top.views
        net.step()
        for _ in range(40):
            before = net.output("Camera.POSITIONS")
            net.step()
            for i, colour in enumerate(("Red", "Green", "Blue")):
                robot = colour + "Robot"
                # a tick late, as in Ikaros 2
                error = np.abs(net.output(f"{robot}.OUTPUT")[0] - before[i]) * [320, 240]
                assert error.max() <= 1.0, (robot, net.tick, error)
                # every marker pixel is in the one cluster: count / (2 pi r²), r = 16
                pixels = net.output(f"{colour}Marker.OUTPUT").sum()
                assert pixels > 200
                assert net.output(f"{robot}.CONFIDENCE")[0] == pytest.approx(
                    pixels / (2 * np.pi * 16 ** 2), rel=1e-6)


def test_attention_focus_is_on_the_red_disc():
    with load("attention.ikg") as net:
        radius = 240 // 24                            # SyntheticCamera's disc radius
        for _ in range(30):
            net.step()
            focus, red = net.output("Saliency.FOCUS"), net.output("Video.POSITIONS")[0]
            assert np.hypot(*((focus - red) * [320, 240])) <= radius + 1, net.tick
            window = net.output("Fovea.OUTPUT")
            assert window.shape == (3, 49, 49)
            reddish = (window[0] > 0.8) & (window[1] < 0.3)
            assert reddish.sum() > 100                # the disc is in the window


def test_marker_cube_finder_finds_the_cubes():
    with load("marker_cube_finder.ikg") as net:
        for _ in range(10):
            net.step()
            assert net.output("Markers.OBJECT_ID").ravel().tolist() == [1, 2, 3]
            truth = net.output("Camera.MARKER_CORNERS").reshape(3, 4, 2).mean(axis=1)
            error = np.abs(net.output("Markers.IMAGE_POSITION") - truth) * [640, 480]
            assert error.max() <= 1.0
            distance = net.output("Markers.MATRIX")[:, 3]
            assert np.allclose(distance, 600 * 0.045 / 80, rtol=0.01)


def test_gallery_canny_edges_lie_on_the_disc_outlines():
    with load("edge_filter_gallery.ikg") as net:
        net.step()
        edges = net.output("Canny.OUTPUT")
        radius = 240 // 24
        rows, cols = np.nonzero(edges)
        rows, cols = rows + 2, cols + 2             # the 5 x 5 kernel's border left out
        for x, y in net.output("Camera.POSITIONS") * [320, 240] - 0.5:
            d = np.hypot(cols - x, rows - y)
            near = d < radius + 4
            assert np.all(np.abs(d[near] - radius) <= 1.5)
            angles = np.arctan2(rows[near] - y, cols[near] - x)
            bins = np.unique(np.floor((angles + np.pi) / (2 * np.pi) * 36).astype(int))
            assert len(bins) >= 0.9 * 36


def test_depth_objects_segments_the_box_from_the_recording():
    from ikaros.hardware.rgbd_recording import box_columns
    with load("depth_objects.ikg") as net:
        for k in range(8):
            net.step()
            left, right = box_columns(k, 8, 160, 40)
            expected = np.zeros((120, 160))
            expected[30:90, left:right] = 1
            assert np.array_equal(net.output("Object.OUTPUT"), expected), k
            assert np.array_equal(net.output("Outline.BOX"), [[left, 30], [right - 1, 30],
                                                              [right - 1, 89], [left, 89]])
            if k >= 3:                    # the box has left its place in the background
                angle = ((left + right) / 2 / 160 - 0.5) * 1.1
                truth = [1500, -1500 * np.tan(angle)]
                assert np.all(np.abs(net.output("Floor.MAXIMA")[0] - truth) < 100), k
