"""Tests of the face detectors on the synthetic camera's face (scikit-image's astronaut),
whose face lies at a known place in the picture."""
import numpy as np
import pytest

from ikaros.testing import load_body


# The astronaut's face in the synthetic camera's face picture, as fractions of the picture:
# (x0, y0, x1, y1), measured on the 240 x 240 crop of data.astronaut() it is made from.
FACE_IN_PICTURE = np.array([55, 50, 148, 143]) / 240


def model(tmp_path, cls, face="yes", extra=""):
    return load_body(tmp_path, f'''
        <module class="SyntheticCamera" name="C" blobs="2" face="{face}" speed="0"/>
        <module class="{cls}" name="D" {extra}/>
        <connection source="C.OUTPUT" target="D.INPUT" delay="0"/>''')


def expected_face(net):
    x0, y0, x1, y1 = net.output("C.FACE_BOUNDS")
    w, h = x1 - x0, y1 - y0
    f = FACE_IN_PICTURE
    return np.array([x0 + f[0] * w, y0 + f[1] * h, x0 + f[2] * w, y0 + f[3] * h])


@pytest.mark.parametrize("cls", ["DFaceDetector", "CIFaceDetector"])
def test_finds_the_face_where_it_is(tmp_path, cls):
    with model(tmp_path, cls) as net:
        net.step()
        assert net.output("D.FACE_COUNT")[0] == 1
        truth = expected_face(net)
        size = truth[2] - truth[0]
        position = net.output("D.FACE_POSITION")[0]
        assert np.allclose(position, [(truth[0] + truth[2]) / 2, (truth[1] + truth[3]) / 2],
                           atol=0.15 * size)
        found = net.output("D.FACE_SIZE")[0]
        assert 0.75 * size < found[0] < 1.35 * size
        bounds = net.output("D.FACE_BOUNDS")[0].reshape(4, 2)
        assert np.allclose(bounds.mean(axis=0), position, atol=1e-6)
        assert net.output("D.FACE_POSITION").shape == (10, 2)
        assert net.output("D.FACE_POSITION")[1:].sum() == 0


@pytest.mark.parametrize("cls", ["DFaceDetector", "CIFaceDetector"])
def test_no_face_no_detection(tmp_path, cls):
    with model(tmp_path, cls, face="no") as net:
        net.step()
        assert net.output("D.FACE_COUNT")[0] == 0
        assert net.output("D.FACE_BOUNDS").sum() == 0


def test_tracking_keeps_the_id_and_counts_life(tmp_path):
    with model(tmp_path, "CIFaceDetector", extra='max_faces="2"') as net:
        ids, lives, novelty = [], [], []
        for _ in range(3):
            net.step()
            ids.append(net.output("D.OBJECT_ID")[0])
            lives.append(net.output("D.LIFE")[0])
            novelty.append(net.output("D.NOVELTY")[0])
        assert ids == [1, 1, 1] and lives == [1, 2, 3] and novelty == [1, 0, 0]
        x0, y0, x1, y1 = net.output("D.FACE_BOUNDS")[0][[0, 1, 4, 5]]
        assert np.allclose(net.output("D.EYE_LEFT_POSITION")[0],
                           [x0 + 0.3 * (x1 - x0), y0 + 0.38 * (y1 - y0)], atol=1e-6)
        assert np.allclose(net.output("D.MOUTH_POSITION")[0],
                           [x0 + 0.5 * (x1 - x0), y0 + 0.78 * (y1 - y0)], atol=1e-6)
        assert net.output("D.SMILE").sum() == 0 and net.output("D.ROTATION").sum() == 0


def test_without_tracking_every_face_is_new(tmp_path):
    with model(tmp_path, "CIFaceDetector", extra='use_tracking="no"') as net:
        net.run(ticks=2)
        assert net.output("D.OBJECT_ID")[0] == 2 and net.output("D.NOVELTY")[0] == 1
        assert net.output("D.LIFE")[0] == 1
