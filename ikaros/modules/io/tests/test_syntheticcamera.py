"""Tests of SyntheticCamera: its truth outputs agree with what its frames show."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

cv2 = pytest.importorskip("cv2")


def test_disc_centroids_are_the_reported_positions(tmp_path):
    net = load(tmp_path, '<module class="SyntheticCamera" name="C" size_x="320" size_y="240" '
                         'blobs="3"/>')
    try:
        for _ in range(3):
            net.step()
            rgb = net.output("C.OUTPUT")
            positions = net.output("C.POSITIONS")
            assert positions.shape == (3, 2)
            for k, (red, green, blue) in enumerate([(1, 0, 0), (0, 1, 0), (0, 0, 1)]):
                plane = [rgb[0], rgb[1], rgb[2]][k]
                others = np.delete(rgb, k, axis=0).max(axis=0)
                mask = (plane > 0.6) & (others < 0.4)
                rows, cols = np.nonzero(mask)
                centre = [(cols.mean() + 0.5) / 320, (rows.mean() + 0.5) / 240]
                assert np.allclose(centre, positions[k], atol=1e-6)
    finally:
        net.close()


def test_markers_are_found_where_reported(tmp_path):
    net = load(tmp_path, '<module class="SyntheticCamera" name="C" blobs="0" markers="4 17"/>')
    try:
        net.step()
        gray = np.rint(net.output("C.INTENSITY") * 255).astype(np.uint8)
        aruco = cv2.aruco
        detector = aruco.ArucoDetector(aruco.getPredefinedDictionary(aruco.DICT_4X4_50))
        corners, ids, _ = detector.detectMarkers(gray)
        assert sorted(ids.ravel()) == [4, 17]
        truth = net.output("C.MARKER_CORNERS").reshape(2, 4, 2) * [640, 480] - 0.5
        found = {int(i): c.reshape(4, 2) for i, c in zip(ids.ravel(), corners)}
        assert np.allclose(found[4], truth[0], atol=1.0)
        assert np.allclose(found[17], truth[1], atol=1.0)
        assert np.array_equal(net.output("C.MARKER_IDS"), [4, 17])
    finally:
        net.close()


def test_the_face_box_holds_the_face(tmp_path):
    net = load(tmp_path, '<module class="SyntheticCamera" name="C" blobs="0" face="yes"/>')
    try:
        x0, y0, x1, y1 = net.output("C.FACE_BOUNDS")
        assert 0.5 < x0 < x1 <= 1 and 0.5 < y0 < y1 <= 1
        inside = net.output("C.OUTPUT")[:, int(y0 * 480):int(y1 * 480), int(x0 * 640):int(x1 * 640)]
        assert inside.std() > 0.1                  # a picture, not the plain floor
    finally:
        net.close()


def test_frames_repeat_for_the_same_tick_and_move_between_ticks(tmp_path):
    net = load(tmp_path, '<module class="SyntheticCamera" name="C"/>')
    try:
        first = net.output("C.OUTPUT").copy()
        net.step()
        assert np.array_equal(net.output("C.OUTPUT"), first)      # init and tick 0: frame 0
        net.step()
        assert not np.array_equal(net.output("C.OUTPUT"), first)
    finally:
        net.close()


def test_bad_marker_id_is_a_load_error(tmp_path):
    with pytest.raises(ModelError, match="marker ids must be 0..49"):
        load(tmp_path, '<module class="SyntheticCamera" name="C" markers="60"/>')


def test_a_drawn_face_without_scikit_image(monkeypatch):
    import sys

    from ikaros.hardware.synthetic_camera import face_image
    monkeypatch.setitem(sys.modules, "skimage", None)       # import skimage fails
    face = face_image(120)
    assert face.shape == (120, 120, 3) and face.dtype == np.uint8
    assert np.array_equal(face[60, 60], [224, 180, 150])     # the skin of the drawn face
    assert np.array_equal(face[2, 2], [200, 200, 200])       # the background
