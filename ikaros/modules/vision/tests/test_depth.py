"""Tests of the depth modules on depth images with known answers and on the synthetic RGB-D
recording played by the Kinect module."""
import math

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.hardware.rgbd_recording import box_columns, raw_to_mm, synthetic_recording
from ikaros.testing import load_body

from vision_models import run

cv2 = pytest.importorskip("cv2")


def matrix_row(x, y, depth):
    """A point as Ikaros 2's DepthTransform reads it: a 3 x 4 matrix, x, y, depth at 3, 7,
    11."""
    return [1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, depth]


def test_depth_transform_turns_image_points_into_points(tmp_path):
    table = np.array([matrix_row(320, 240, 1000),     # the centre of a 640 x 480 image
                      matrix_row(480, 240, 2000),     # a quarter of the width right
                      matrix_row(320, 60, 500)], np.float32)   # three eighths up
    with run(tmp_path, "DepthTransform", {"INPUT": table}) as net:
        out = net.output("M.OUTPUT")
    f = 320 / math.tan(0.55)                           # (x_res / 2) / tan(fov_h / 2)
    g = 240 / math.tan(0.55)
    assert np.allclose(out[0], matrix_row(1000, 0, 0), atol=1e-3)
    assert np.allclose(out[1], matrix_row(2000, 2000 * (320 - 480) / f, 0), atol=1e-2)
    assert np.allclose(out[2], matrix_row(500, 0, 500 * (60 - 240) / g), atol=1e-2)


def test_depth_transform_reads_rows_of_other_widths_as_the_original(tmp_path):
    """Ikaros 2's golden outputs: INPUT.size // 12 points, each read from the start of its
    row on and written as 16 values from the start of its output row on."""
    data = np.arange(40, dtype=np.float32).reshape(5, 8) / 10
    with run(tmp_path, "DepthTransform", {"INPUT": data}) as net:
        out = net.output("M.OUTPUT")
        assert any("rows are 8 wide" in m for *_, m in net.log)
    expected = np.zeros(40)
    f, g = 320 / math.tan(0.55), 240 / math.tan(0.55)
    for i in range(40 // 12):                           # 3 points
        x, y, d = data.ravel()[i * 8 + np.array([3, 7, 11])]
        m = np.eye(4)
        m[:3, 3] = d, d * (320 - x) / f, d * (y - 240) / g
        expected[i * 8:i * 8 + 16] = m.ravel()
    assert np.allclose(out.ravel(), expected, atol=1e-5)


def planes_image():
    depth = np.zeros((60, 80), np.float32)
    depth.flat[:1200] = 500
    depth.flat[1200:3200] = 1000
    depth.flat[3200:3500] = 300
    return depth


def test_depth_histogram_counts_and_finds_the_nearest_object(tmp_path):
    with run(tmp_path, "DepthHistogram", {"INPUT": planes_image()}, filter="no",
             threshold="500") as net:
        counts, obj = net.output("M.OUTPUT"), net.output("M.OBJECT")
    assert counts.shape == (128,) and counts.sum() == 3500
    assert counts[500 // 16] == 1200 and counts[1000 // 16] == 2000 and counts[300 // 16] == 300
    assert np.array_equal(obj, [496, 512, 1200])


def test_depth_histogram_filter_smooths(tmp_path):
    with run(tmp_path, "DepthHistogram", {"INPUT": planes_image()}, threshold="500") as net:
        counts, obj = net.output("M.OUTPUT"), net.output("M.OBJECT")
    assert counts[31] == 600 and counts[30] == 300 and counts[62] == 1000
    assert np.array_equal(obj, [496, 512, 600])


def test_depth_segmentation_cuts_the_range_and_masks(tmp_path):
    depth = planes_image()
    with run(tmp_path, "DepthSegmentation", {"INPUT": depth, "OBJECT": [496, 512, 1200]},
             mask_right="0.5") as net:
        out = net.output("M.OUTPUT")
    expected = (depth >= 496) & (depth < 512)
    expected[:, 40:] = False
    assert np.array_equal(out, expected)


def test_depth_point_list(tmp_path):
    depth = np.array([[1000, 2000], [0, 500]], np.float32)
    red, green, blue = depth / 2000, depth / 4000, np.ones((2, 2), np.float32)
    with run(tmp_path, "DepthPointList", {"RED": red, "GREEN": green, "BLUE": blue,
                                          "DEPTH": depth}, fov_h="1.0", fov_v="0.5") as net:
        out = net.output("M.OUTPUT")
    assert out.shape == (4, 19)
    for k, (r, c) in enumerate([(0, 0), (0, 1), (1, 0), (1, 1)]):
        d = depth[r, c]
        right, up = ((c + 0.5) / 2 - 0.5) * 1.0, (0.5 - (r + 0.5) / 2) * 0.5
        matrix = np.eye(4)
        matrix[:3, 3] = d, -d * math.tan(right), d * math.tan(up)
        assert np.allclose(out[k, :16], matrix.ravel(), atol=1e-3)
        assert np.allclose(out[k, 16:], [red[r, c], green[r, c], 1])


def test_contour_trace_of_a_rectangle(tmp_path):
    image = np.zeros((60, 80), np.float32)
    image[10:40, 20:70] = 1
    with run(tmp_path, "DepthContourTrace", {"INPUT": image}, segment_length="10",
             segment_smoothing="0") as net:
        segments, box = net.output("M.OUTPUT"), net.output("M.BOX")
        count = int(net.output("M.LENGTH")[0])
        debug = net.output("M.DEBUG")
    assert np.array_equal(box, [[20, 10], [69, 10], [69, 39], [20, 39]])
    perimeter = 2 * (49 + 29)
    assert count == perimeter // 10 and segments[count:].sum() == 0
    ends = segments[:count].reshape(-1, 2)
    on_edge = (np.isclose(ends[:, 0], 20) | np.isclose(ends[:, 0], 69) |
               np.isclose(ends[:, 1], 10) | np.isclose(ends[:, 1], 39))
    assert on_edge.all()
    chords = np.hypot(*(segments[:count, 2:] - segments[:count, :2]).T)
    step = perimeter / count                      # equal steps along the outline
    assert np.all(chords <= step + 1e-3) and np.all(chords >= step / math.sqrt(2) - 1e-3)
    assert np.sum(np.isclose(chords, step, atol=1e-3)) >= count - 4   # shorter at corners
    assert debug.shape == (60, 80) and debug.max() == 1 and debug[25, 45] == 0.5


def test_kinect_plays_a_recording(tmp_path):
    synthetic_recording(tmp_path / "rgbd.npz", frames=3)
    with np.load(tmp_path / "rgbd.npz") as data:
        raw, rgb = data["depth"], data["rgb"]
    net = load_body(tmp_path, '<module class="Kinect" name="K" recording="rgbd.npz" '
                              'mode="mm"/><module class="Kinect" name="R" '
                              'recording="rgbd.npz"/>')
    with net:
        for k in [0, 0, 1, 2, 0]:              # init and tick k show frame k, repeating
            assert np.allclose(net.output("K.DEPTH"), raw_to_mm(raw[k]))
            assert np.allclose(net.output("R.DEPTH"), raw[k] / 2047)
            assert np.allclose(net.output("K.OUTPUT"), rgb[k].transpose(2, 0, 1) / 255)
            assert np.allclose(net.output("K.INTENSITY"), rgb[k].mean(axis=2) / 255)
            net.step()
    assert abs(raw_to_mm(raw[0])[0, 0] - 3000) < 10


def test_kinect_without_a_device_library_names_it(tmp_path):
    with pytest.raises(ModelError, match="Kinect needs libfreenect and its Python bindings"):
        load_body(tmp_path, '<module class="Kinect" name="K"/>')
    with pytest.raises(ModelError, match="OpenNI 2"):
        load_body(tmp_path, '<module class="Kinect" name="K" xtion="yes"/>')


def test_depth_blob_list_finds_the_box_that_moved_in(tmp_path):
    frames, cols = 5, 160
    synthetic_recording(tmp_path / "rgbd.npz", frames=frames, cols=cols)
    net = load_body(tmp_path, '''
        <module class="Kinect" name="K" recording="rgbd.npz" mode="mm"/>
        <module class="DepthBlobList" name="B" min_points="1"/>
        <connection source="K.DEPTH" target="B.INPUT" delay="0"/>''')
    with net:
        net.run(ticks=frames)                  # the box is at the right edge now
        left, right = box_columns(frames - 1, frames, cols, cols // 4)
        angle = ((left + right) / 2 / cols - 0.5) * 1.1
        expected = [1500, -1500 * math.tan(angle)]
        maxima = net.output("B.MAXIMA")
        assert np.all(np.abs(maxima[0] - expected) < 100)
        assert maxima[1:].sum() == 0                    # one object, one maximum
        assert net.output("B.OUTPUT")[0, 16] > 0.2
        assert np.allclose(net.output("B.OUTPUT")[0, [3, 7]], maxima[0])
        assert net.output("B.DETECTION").sum() > 0
        assert net.output("B.BACKGROUND").sum() > net.output("B.DETECTION").sum()
