"""Tests of the OutputVideoFile module: movies are read back with imageio."""
import numpy as np

from ikaros.testing import load_body as load

import imageio.v3 as iio
import imageio_ffmpeg  # noqa: F401  (the video extra; part of the test extras)


def read_movie(path):
    frames = iio.imread(path, plugin="FFMPEG")                 # (n, rows, cols, 3) uint8
    meta = iio.immeta(path, plugin="FFMPEG")
    return frames.astype(np.float64) / 255, meta


def test_gray_frames_one_per_tick(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" outputsize_x="16" outputsize_y="8" '
                         'min="0" max="1" step="0.2"/>\n'
                         '<module class="OutputVideoFile" name="V" filename="g.mp4" '
                         'frame_rate="10" quality="high"/>\n'
                         '<connection source="S.OUTPUT" target="V.INTENSITY" delay="0"/>')
    try:
        net.run(ticks=5)
    finally:
        net.close()                                             # finishes the file
    frames, meta = read_movie(tmp_path / "g.mp4")
    assert frames.shape == (5, 8, 16, 3)
    assert meta["fps"] == 10
    for k, frame in enumerate(frames):
        assert np.allclose(frame, 0.2 * (k + 1), atol=0.03), k


def test_colour_input_and_odd_size(tmp_path):
    colour = "0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9; " \
             "0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1; " \
             "0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5"
    net = load(tmp_path, f'<module class="Constant" name="C" data="{colour}"/>\n'
                         '<module class="OutputVideoFile" name="V" filename="c.mp4"/>\n'
                         '<connection source="C.OUTPUT" target="V.RED" delay="0" '
                         'sourceoffset="0" size="15"/>\n'
                         '<connection source="C.OUTPUT" target="V.GREEN" delay="0" '
                         'sourceoffset="15" size="15"/>\n'
                         '<connection source="C.OUTPUT" target="V.BLUE" delay="0" '
                         'sourceoffset="30" size="15"/>')
    try:
        net.run(ticks=3)
    finally:
        net.close()
    frames, meta = read_movie(tmp_path / "c.mp4")
    assert len(frames) == 3 and meta["fps"] == 25
    assert frames.shape[1] % 2 == 0 and frames.shape[2] % 2 == 0   # scaled to even sizes
    assert np.allclose(frames[..., 0], 0.9, atol=0.04)
    assert np.allclose(frames[..., 1], 0.1, atol=0.04)
    assert np.allclose(frames[..., 2], 0.5, atol=0.04)


def test_round_trip_through_inputvideofile(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0.8 0.8; 0.8 0.8"/>\n'
                         '<module class="Constant" name="Z" data="0.3 0.3; 0.3 0.3"/>\n'
                         '<module class="OutputVideoFile" name="V" filename="r.mp4"/>\n'
                         '<connection source="C.OUTPUT" target="V.RED" delay="0"/>\n'
                         '<connection source="Z.OUTPUT" target="V.BLUE" delay="0"/>')
    try:
        net.run(ticks=2)
    finally:
        net.close()
    net = load(tmp_path, '<module class="InputVideoFile" name="I" filename="r.mp4"/>')
    try:
        net.step()
        assert np.allclose(net.output("I.OUTPUT").mean(axis=(1, 2)), [0.8, 0, 0.3],
                           atol=0.05)
    finally:
        net.close()
