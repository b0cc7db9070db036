"""The tracking examples follow the template through the example movie: the movie is a
picture seen through a known affine camera (scripts/make_tracking_movie.py), so where the
centre of the first frame is in every later frame is known."""
import importlib.util
import os

import numpy as np
import pytest

import ikaros

pytest.importorskip("cv2")
pytest.importorskip("imageio_ffmpeg")

ROOT = os.path.join(os.path.dirname(__file__), *[os.pardir] * 4)
EXAMPLES = os.path.join(ROOT, "examples", "modules")


def movie_camera():
    spec = importlib.util.spec_from_file_location(
        "make_tracking_movie", os.path.join(ROOT, "scripts", "make_tracking_movie.py"))
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    return script.camera, script.FRAMES


def truth(camera, k):
    """Where the centre of frame 0 (the learned template's) is in frame k, in 0..1."""
    first = np.vstack([camera(0), [0, 0, 1]])
    picture = np.linalg.solve(first, [159.5, 119.5, 1])
    return (camera(k) @ picture + 0.5) / [320, 240]


@pytest.mark.slow
@pytest.mark.parametrize("example, statuses", [
    ("RobustTransformEstimator_example.ikg", None),
    ("TemplateTrackingController_example.ikg", {2}),
    ("PyramidalLucasKanadeTracker_example.ikg", None)])
def test_the_outline_follows_the_centre_of_the_first_frame(example, statuses):
    camera, frames = movie_camera()
    with ikaros.load(os.path.join(EXAMPLES, example)) as net:
        for k in range(frames + 4):                  # once round the loop, and on
            net.step()
            location = net.output("Outline.LOCATION")
            assert location[2] == 1, (example, k)
            error = np.abs(location[:2] - truth(camera, k % frames)) * [320, 240]
            assert error.max() <= 2.0, (example, k, error)
            if statuses:
                assert net.output("Controller.STATUS")[0] in statuses
