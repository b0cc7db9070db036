"""Tests of the camera inputs (InputVideo, InputVideoStream, NetworkCamera, InputVideoAV)
against the synthetic scene, movie files in tmp_path and the loopback MJPEG server."""
import time

import numpy as np
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.hardware.mjpeg import MJPEGReader, MJPEGServer
from ikaros.hardware.synthetic_camera import SyntheticScene
from ikaros.testing import load_body as load

cv2 = pytest.importorskip("cv2")

ROWS, COLS = 96, 128


@pytest.fixture
def scene():
    return SyntheticScene(ROWS, COLS, blobs=2)


@pytest.fixture
def server(scene):
    with MJPEGServer(lambda n: scene.frame(n)[0], fps=50, quality=95) as s:
        yield s


def wait_for(condition, seconds=5.0):
    end = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < end, "timed out"
        time.sleep(0.02)


def planes_of(rgb):
    return rgb.transpose(2, 0, 1).astype(np.float32) / 255


def assert_is_scene_frame(net, name, scene, atol=0.06):
    """The outputs show one of the scene's frames (JPEG changes values a little)."""
    out = net.output(f"{name}.OUTPUT")
    errors = [np.abs(out - planes_of(scene.frame(n)[0])).mean() for n in range(400)]
    assert min(errors) < 0.01
    assert np.allclose(net.output(f"{name}.INTENSITY"), out.mean(axis=0), atol=1e-6)
    assert np.array_equal(net.output(f"{name}.RED"), out[0])


def test_reader_reads_the_served_frames(server, scene):
    reader = MJPEGReader(server.url, timeout=2)
    try:
        first = reader.read()
        assert first.shape == (ROWS, COLS, 3) and first.dtype == np.uint8
        assert np.abs(first.astype(int) - scene.frame(0)[0]).mean() < 2
    finally:
        reader.close()


def test_reader_polls_a_snapshot_url(server, scene):
    reader = MJPEGReader(server.url_snapshot, timeout=2)
    try:
        for _ in range(2):
            assert np.abs(reader.read().astype(int) - scene.frame(0)[0]).mean() < 2
    finally:
        reader.close()


def test_network_camera_end_to_end(tmp_path, server, scene):
    net = load(tmp_path, f'<module class="NetworkCamera" name="C" host_ip="127.0.0.1" '
                         f'host_port="{server.port}" image_request="/video.mjpg"/>')
    try:
        assert net.output("C.OUTPUT").shape == (3, ROWS, COLS)
        net.step()
        first = net.output("C.OUTPUT").copy()
        assert_is_scene_frame(net, "C", scene)
        assert net.output("C.STALE")[0] == 0
        assert 0 <= net.output("C.FRAME_AGE")[0] < 1.0
        time.sleep(0.2)
        net.step()
        assert not np.array_equal(net.output("C.OUTPUT"), first)    # newer frames arrive
    finally:
        net.close()


def test_network_camera_asks_for_fps_and_compression(tmp_path, server):
    net = load(tmp_path, f'<module class="NetworkCamera" name="C" host_ip="127.0.0.1" '
                         f'host_port="{server.port}" fps="5" compression="30"/>')
    try:
        assert server.requests[0] == "/axis-cgi/mjpg/video.cgi?fps=5&compression=30"
    finally:
        net.close()


def test_stream_is_scaled_to_size(tmp_path, server):
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'size_x="64" size_y="48"/>')
    try:
        net.step()
        assert net.output("S.OUTPUT").shape == (3, 48, 64)
        assert 0.1 < net.output("S.INTENSITY").mean() < 0.5
    finally:
        net.close()


def test_a_stream_that_stops_gives_stale_and_a_warning_without_blocking(tmp_path, server):
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'size_x="{COLS}" size_y="{ROWS}" timeout="0.5"/>')
    try:
        net.step()
        assert net.output("S.STALE")[0] == 0
        server.pause()                                  # connection open, nothing sent
        start = time.monotonic()
        while net.output("S.STALE")[0] == 0:
            t = time.monotonic()
            net.step()
            assert time.monotonic() - t < 0.1           # a tick never waits for the stream
            assert time.monotonic() - start < 3
            time.sleep(0.05)
        assert net.output("S.FRAME_AGE")[0] > 0.5
        assert any("no new frame" in m for *_, m in net.log)
        server.resume()                                 # the reader reconnects
        wait_for(lambda: (net.step(), net.output("S.STALE")[0] == 0)[1], 6)
    finally:
        net.close()


def test_a_server_that_goes_away_gives_stale(tmp_path, scene):
    server = MJPEGServer(lambda n: scene.frame(n)[0], fps=50)
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'timeout="0.4"/>')
    try:
        net.step()
        server.close()
        wait_for(lambda: (net.step(), net.output("S.STALE")[0] == 1)[1], 3)
    finally:
        net.close()
        server.close()


def test_no_server_is_a_clear_load_error(tmp_path):
    with pytest.raises(ModelError, match=r'cannot open stream "http://127.0.0.1:9/x.mjpg"'):
        load(tmp_path, '<module class="InputVideoStream" name="S" '
                       'url="http://127.0.0.1:9/x.mjpg" timeout="0.5"/>')


def test_a_server_that_sends_nothing_is_a_load_error_in_bounded_time(tmp_path, server):
    server.pause()
    start = time.monotonic()
    with pytest.raises(ModelError, match="no frame from stream .* within 0.5 s"):
        load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                       f'timeout="0.5"/>')
    assert time.monotonic() - start < 3


def test_stream_needs_a_url(tmp_path):
    with pytest.raises(ModelError, match="InputVideoStream needs a url"):
        load(tmp_path, '<module class="InputVideoStream" name="S"/>')


def write_movie(path, scene, frames=12, fps=25):
    writer = cv2.VideoWriter(str(path), cv2.VideoWriter_fourcc(*"MJPG"), fps, (COLS, ROWS))
    for n in range(frames):
        writer.write(scene.frame(n)[0][:, :, ::-1])
    writer.release()


def test_input_video_opens_a_device_path(tmp_path, scene):
    write_movie(tmp_path / "cam.avi", scene)
    net = load(tmp_path, f'<module class="InputVideo" name="V" device="{tmp_path}/cam.avi" '
                         f'size_x="{COLS}" size_y="{ROWS}"/>')
    try:
        net.step()
        assert_is_scene_frame(net, "V", scene)
    finally:
        net.close()


def test_a_missing_camera_is_a_clear_load_error(tmp_path):
    with pytest.raises(ModelError, match='cannot open camera "/dev/no-such-camera"'):
        load(tmp_path, '<module class="InputVideo" name="V" device="/dev/no-such-camera"/>')


def test_input_video_av_plays_a_file_then_ends(tmp_path, scene):
    write_movie(tmp_path / "m.avi", scene, frames=6, fps=50)
    net = load(tmp_path, f'<module class="InputVideoAV" name="A" filename="m.avi" '
                         f'size_x="{COLS}" size_y="{ROWS}" flip="yes"/>')
    try:
        out = net.output("A.OUTPUT")
        assert np.abs(out[:, :, ::-1] - planes_of(scene.frame(0)[0])).mean() < 0.01   # flipped
        with pytest.raises(RunError, match="end_of_file"):
            for _ in range(200):
                net.step()
                time.sleep(0.01)
    finally:
        net.close()


def test_input_video_av_reads_a_stream(tmp_path, server, scene):
    net = load(tmp_path, f'<module class="InputVideoAV" name="A" url="{server.url}" '
                         f'size_x="{COLS}" size_y="{ROWS}"/>')
    try:
        net.step()
        assert_is_scene_frame(net, "A", scene)
    finally:
        net.close()


def test_closing_while_the_stream_hangs_returns_at_once(tmp_path, server):
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'timeout="5"/>')
    net.step()
    server.pause()                      # the grab thread now waits in a read (up to 5 s)
    time.sleep(0.2)
    start = time.monotonic()
    net.close()
    assert time.monotonic() - start < 1.0


@pytest.fixture
def file_server(tmp_path):
    """An HTTP server on 127.0.0.1 for the files in tmp_path; yields its base URL."""
    import functools
    import threading
    from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer

    class Quiet(SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    httpd = ThreadingHTTPServer(("127.0.0.1", 0),
                                functools.partial(Quiet, directory=str(tmp_path)))
    thread = threading.Thread(target=httpd.serve_forever, args=(0.05,), daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()
    httpd.server_close()


def test_a_stream_that_is_not_mjpeg_goes_through_ffmpeg(tmp_path, scene, file_server):
    write_movie(tmp_path / "clip.avi", scene, frames=30)
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" '
                         f'url="{file_server}/clip.avi" size_x="{COLS}" size_y="{ROWS}"/>')
    with net:
        net.step()
        assert_is_scene_frame(net, "S", scene)


def test_an_http_error_is_a_clear_load_error(tmp_path, file_server):
    with pytest.raises(ModelError, match=r'cannot open stream ".*/missing.mjpg": HTTP 404'):
        load(tmp_path, f'<module class="InputVideoStream" name="S" '
                       f'url="{file_server}/missing.mjpg"/>')


def test_input_video_finds_a_camera_by_its_name(tmp_path, monkeypatch):
    from ikaros.modules.io import InputVideo
    for number, name in ((0, "Integrated Webcam"), (2, "USB Camera: HD Pro Webcam C920")):
        folder = tmp_path / "sys" / f"video{number}"
        folder.mkdir(parents=True)
        (folder / "name").write_text(name + "\n")
    monkeypatch.setattr(InputVideo, "VIDEO4LINUX", str(tmp_path / "sys"))
    assert InputVideo.camera_named("c920") == "/dev/video2"
    with pytest.raises(ValueError, match='no camera named "Kinect" .cameras: video0: '
                                         'Integrated Webcam; video2: USB Camera'):
        InputVideo.camera_named("Kinect")
    with pytest.raises(ModelError, match='cannot open camera "/dev/video2"'):
        load(tmp_path, '<module class="InputVideo" name="V" device_name="HD Pro"/>')


def test_input_video_by_device_index_and_ikaros_3_sizes(tmp_path, scene):
    write_movie(tmp_path / "cam.avi", scene)
    with pytest.raises(ModelError, match="cannot open camera 7"):
        load(tmp_path, '<module class="InputVideo" name="V" device_index="7" id="1"/>')
    net = load(tmp_path, f'<module class="InputVideo" name="V" device="{tmp_path}/cam.avi" '
                         f'device_index="7"/>', dialect="3")
    try:
        assert net.output("V.OUTPUT").shape == (3, 720, 1280)       # Ikaros 3's defaults
    finally:
        net.close()


def frame_number(net, name, scene):
    out = net.output(f"{name}.OUTPUT")
    errors = [np.abs(out - planes_of(scene.frame(n)[0])).mean() for n in range(300)]
    assert min(errors) < 0.01
    return int(np.argmin(errors))


def test_a_synchronized_stream_shows_every_frame_in_turn(tmp_path, server, scene):
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'size_x="{COLS}" size_y="{ROWS}" synchronized_framegrabber="yes" '
                         f'synchronized_tick="yes"/>')
    try:
        numbers = []
        for _ in range(6):
            net.step()
            numbers.append(frame_number(net, "S", scene))
            time.sleep(0.06)                    # slower than the stream's 50 frames/s
        assert np.diff(numbers[1:]).tolist() == [1, 1, 1, 1]
    finally:
        net.close()


def test_unsynchronized_ticks_skip_frames_and_ikaros_3_waits_for_a_new_one(tmp_path, server,
                                                                           scene):
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'size_x="{COLS}" size_y="{ROWS}"/>')
    try:
        numbers = []
        for _ in range(4):
            net.step()
            numbers.append(frame_number(net, "S", scene))
            time.sleep(0.1)
        assert min(np.diff(numbers)) > 1        # the newest frame: others were skipped
    finally:
        net.close()
    net = load(tmp_path, f'<module class="InputVideoStream" name="S" url="{server.url}" '
                         f'size_x="{COLS}" size_y="{ROWS}"/>', dialect="3")
    try:
        numbers = []
        for _ in range(4):
            net.step()                          # no pause: each tick waits for a frame
            numbers.append(frame_number(net, "S", scene))
        assert min(np.diff(numbers)) >= 1
    finally:
        net.close()
