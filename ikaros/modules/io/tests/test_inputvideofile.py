"""Tests of the InputVideoFile module (movies made with imageio in tmp_path)."""
import numpy as np
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.module import PRINT
from ikaros.testing import load_body as load

import imageio.v3 as iio
import imageio_ffmpeg  # noqa: F401  (the video extra; part of the test extras)

COLOURS = [(200, 30, 60), (20, 220, 100), (90, 90, 240), (128, 128, 128)]


def make_movie(path, colours=COLOURS, rows=16, cols=24):
    frames = np.array([np.full((rows, cols, 3), c, np.uint8) for c in colours])
    iio.imwrite(path, frames, plugin="FFMPEG", fps=10, quality=9, macro_block_size=1)


def assert_colour(net, colour, tol=0.04):
    c = np.array(colour) / 255
    assert np.allclose(net.output("I.OUTPUT").mean(axis=(1, 2)), c, atol=tol)
    assert np.allclose(net.output("I.RED"), c[0], atol=tol)
    assert np.allclose(net.output("I.GREEN"), c[1], atol=tol)
    assert np.allclose(net.output("I.BLUE"), c[2], atol=tol)
    planes = net.output("I.OUTPUT")
    assert np.allclose(net.output("I.INTENSITY"), planes.mean(axis=0), atol=1e-6)


def test_one_frame_per_tick_then_end_of_file(tmp_path):
    make_movie(tmp_path / "m.mp4")
    net = load(tmp_path, '<module class="InputVideoFile" name="I" filename="m.mp4"/>')
    try:
        assert net.output("I.OUTPUT").shape == (3, 16, 24)
        assert net.output("I.RESTART").shape == (1,)
        assert_colour(net, COLOURS[0])                     # the first frame in init
        assert net.output("I.RESTART")[0] == 0
        restarts = []
        for tick, colour in enumerate(COLOURS):
            net.step()
            assert_colour(net, colour)
            restarts.append(float(net.output("I.RESTART")[0]))
        assert restarts == [1, 0, 0, 0]
        with pytest.raises(RunError, match="end_of_file"):
            net.step()                                     # the run ended on the last frame
        assert net.tick == 4
    finally:
        net.close()


def test_loop_restarts_with_a_restart_pulse(tmp_path):
    make_movie(tmp_path / "m.mp4", COLOURS[:2])
    net = load(tmp_path, '<module class="InputVideoFile" name="I" filename="m.mp4" '
                         'loop="yes"/>')
    try:
        restarts = []
        for tick in range(7):
            net.step()
            assert_colour(net, COLOURS[tick % 2])
            restarts.append(float(net.output("I.RESTART")[0]))
        assert restarts == [1, 0, 1, 0, 1, 0, 1]
    finally:
        net.close()


def test_scaling_and_aspect_ratio(tmp_path):
    make_movie(tmp_path / "m.mp4", COLOURS[:1], rows=16, cols=32)
    net = load(tmp_path, '<module class="InputVideoFile" name="I" filename="m.mp4" '
                         'size_x="8" info="yes"/>\n'
                         '<module class="InputVideoFile" name="J" filename="m.mp4" '
                         'size_x="6" size_y="10"/>')
    try:
        assert net.output("I.OUTPUT").shape == (3, 4, 8)
        assert net.output("J.INTENSITY").shape == (10, 6)
        net.step()
        assert_colour(net, COLOURS[0])
        assert any(e[1] == PRINT and "h264" in e[3] for e in net.log)
    finally:
        net.close()


def test_missing_file_is_a_build_error(tmp_path):
    with pytest.raises(ModelError, match="nothere.mp4"):
        load(tmp_path, '<module class="InputVideoFile" name="I" filename="nothere.mp4"/>')
    (tmp_path / "junk.mp4").write_bytes(b"not a movie")
    with pytest.raises(ModelError, match="junk.mp4"):
        load(tmp_path, '<module class="InputVideoFile" name="I" filename="junk.mp4"/>')
