"""The web UI's images: both encoders (OpenCV when installed, else Pillow) give the image
the array holds, colours in their order; each image is encoded once per tick whatever the
number of clients, and only for a client that asks for it."""
from __future__ import annotations

import io
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.request
import warnings

import numpy as np
import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros import priority  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui import encoding, snapshot  # noqa: E402
from ikaros.webui.encoding import (JPEG_QUALITY, decode_frame, image_bytes,  # noqa: E402
                                   image_encoder, image_pixels)
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

Image = pytest.importorskip("PIL.Image")
pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

ENCODERS = ("opencv", "pillow")


def _levels(array) -> np.ndarray:
    """The 8-bit levels a browser should see, computed plainly: each value as float32,
    NaN as 0, clipped to 0..1, times 255 and plus 0.5 (in float32), rounded down."""
    a = np.asarray(array, dtype=np.float32)
    a = np.clip(np.where(np.isnan(a), np.float32(0), a), np.float32(0), np.float32(1))
    return np.floor(a * np.float32(255) + np.float32(0.5)).astype(np.int64)


def _decoded(file: bytes) -> np.ndarray:
    """A file's pixels as ikaros lays them out: (rows, cols) gray, (3, rows, cols) colour."""
    pixels = np.asarray(Image.open(io.BytesIO(file))).astype(np.int64)
    return pixels.transpose(2, 0, 1) if pixels.ndim == 3 else pixels


def _colour_image(rows=48, cols=64) -> np.ndarray:
    """Smooth planes that differ: red rises to the right, green downwards, blue is 0.2;
    the corner blocks are pure red, green, blue and white."""
    y, x = np.mgrid[0:rows, 0:cols]
    image = np.stack([x / (cols - 1), y / (rows - 1), np.full((rows, cols), 0.2)])
    for (r, c), colour in zip([(0, 0), (0, cols - 16), (rows - 16, 0), (rows - 16, cols - 16)],
                              [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]):
        image[:, r:r + 16, c:c + 16] = np.reshape(colour, (3, 1, 1))
    return image.astype(np.float32)


def test_the_levels_are_the_values_clipped_and_rounded_half_up():
    edges = np.array([np.nan, np.inf, -np.inf, -1, 0, 1, 2, 1e38, -1e38, 0.5 / 255,
                      np.nextafter(np.float32(0.5 / 255), np.float32(0)), 127.5 / 255,
                      0.25, 0.5, 0.999], np.float32)
    rng = np.random.default_rng(3)
    values = np.concatenate([edges, rng.standard_normal(10000).astype(np.float32),
                             rng.random(10000).astype(np.float32)])
    got = image_pixels(values.reshape(-1, 1))
    assert got.dtype == np.uint8
    assert got.ravel().tolist() == _levels(values).tolist()
    assert image_pixels(_colour_image()).shape == (3, 48, 64)


@pytest.mark.parametrize("encoder", ENCODERS)
def test_a_png_image_is_the_arrays_levels_exactly(encoder):
    colour = _colour_image()
    gray = colour[0] * 0.5 + colour[1] * 0.5
    for image in (colour, gray):
        file = image_bytes(image, "png", encoder=encoder)
        assert Image.open(io.BytesIO(file)).format == "PNG"
        assert _decoded(file).tolist() == _levels(image).tolist()


@pytest.mark.parametrize("encoder", ENCODERS)
def test_a_jpeg_image_is_the_array_within_jpegs_loss_in_its_colours(encoder):
    colour = _colour_image()
    decoded = _decoded(image_bytes(colour, "jpeg", encoder=encoder))
    assert decoded.shape == (3, 48, 64)
    # the smooth middle (JPEG halves the colours' resolution: their edges blur)
    error = np.abs(decoded - _levels(colour))[:, :, 24:40]
    assert error.mean() < 2.0 and error.max() <= 8
    # the planes in their order: each corner block is the colour it was given
    for (r, c), colour_ in zip([(4, 4), (4, 52), (36, 4), (36, 52)],
                               [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)]):
        block = decoded[:, r:r + 8, c:c + 8].reshape(3, -1)
        assert np.abs(block - np.reshape(colour_, (3, 1))).max() <= 6, (r, c, block[:, 0])
    gray = colour[0] * 0.5 + colour[1] * 0.5
    decoded = _decoded(image_bytes(gray, "jpeg", encoder=encoder))
    assert decoded.shape == (48, 64)
    assert np.abs(decoded - _levels(gray)).max() <= 4


def test_the_two_encoders_show_the_same_image():
    colour = _colour_image()
    for image in (colour, colour[1]):
        for quality in (13, JPEG_QUALITY):
            by_opencv, by_pillow = (_decoded(image_bytes(image, "jpeg", quality, encoder=e))
                                    for e in ENCODERS)
            assert np.abs(by_opencv - by_pillow).max() <= 2


@pytest.mark.parametrize("encoder", ENCODERS)
def test_the_jpeg_quality_is_the_one_given(encoder):
    colour = _colour_image()
    for quality in (13, JPEG_QUALITY):
        expected = io.BytesIO()
        Image.fromarray(np.zeros((8, 8, 3), np.uint8), "RGB").save(expected, "JPEG",
                                                                   quality=quality)
        file = image_bytes(colour, "jpeg", quality, encoder=encoder)
        # the quantisation tables are what the quality sets
        assert Image.open(io.BytesIO(file)).quantization == \
            Image.open(expected).quantization


def test_opencv_encodes_when_it_is_installed_and_pillow_otherwise(monkeypatch):
    pytest.importorskip("cv2")
    assert image_encoder() == "opencv"
    monkeypatch.setattr(encoding, "_opencv", lambda: None)
    assert image_encoder() == "pillow"
    colour = _colour_image()
    assert image_bytes(colour, "png") == image_bytes(colour, "png", encoder="pillow")


def test_a_bad_image_or_format_is_refused():
    with pytest.raises(ValueError, match=r"an image must be \(rows, cols\) or \(3, rows, "
                                         r"cols\), not \(4, 2, 2\)"):
        image_bytes(np.zeros((4, 2, 2)), "png")
    with pytest.raises(ValueError, match='unknown image format "gif"'):
        image_bytes(np.zeros((2, 2)), "gif")


MODEL = """<?xml version="1.0"?>
<group name="T">
    <module class="Randomizer" name="A" outputsize_x="16" outputsize_y="12" seed="1" />
    <module class="Randomizer" name="B" outputsize_x="8" outputsize_y="6" seed="2" />
</group>
"""


def _frame(ws):
    while True:
        m = ws.receive()
        if m.get("bytes") is not None:
            return decode_frame(m["bytes"])


def test_each_image_is_encoded_once_per_tick_and_only_for_a_client_that_asks(
        tmp_path, monkeypatch):
    encoded = []                            # (what, content) of every image encoded
    plain = snapshot.encode_array

    def recording(array, fmt, quality=JPEG_QUALITY):
        if fmt in encoding.IMAGE_FORMATS:
            encoded.append((array.shape, fmt, array.tobytes()))
        return plain(array, fmt, quality)
    monkeypatch.setattr(snapshot, "encode_array", recording)
    path = tmp_path / "t.ikg"
    path.write_text(MODEL)
    net = ikaros.load(str(path))
    net.log_level = WARNING
    a, b = (12, 16), (6, 8)
    try:
        with TestClient(create_app(net)) as client, \
                client.websocket_connect("/api/ws") as one, \
                client.websocket_connect("/api/ws") as two, \
                client.websocket_connect("/api/ws") as once:
            client.post("/api/control", json={"state": "play"})
            one.send_json({"type": "subscribe", "buffers": [
                {"path": "A.OUTPUT", "format": "jpeg"}, {"path": "B.OUTPUT", "format": "raw"}]})
            two.send_json({"type": "subscribe", "buffers": [
                {"path": "A.OUTPUT", "format": "jpeg"}]})
            once.send_json({"type": "subscribe", "buffers": [
                {"path": "B.OUTPUT", "format": "png"}]})
            for ws in (one, two, once):
                ws.send_json({"type": "ready"})
            _frame(once)                    # and it never asks again
            ticks = set()
            for _ in range(8):
                for ws in (one, two):
                    header, _ = _frame(ws)
                    ticks.add(header["tick"])
                    ws.send_json({"type": "ready"})
    finally:
        net.controller.stop()
        net.controller.join(10)
        net.close()
    images_of_a = [content for shape, fmt, content in encoded if shape == a]
    assert {(shape, fmt) for shape, fmt, _ in encoded} == {(a, "jpeg"), (b, "png")}
    assert len([1 for shape, _, _ in encoded if shape == b]) == 1
    # A's values are new every tick: an image encoded twice for a tick would repeat one
    assert len(set(images_of_a)) == len(images_of_a)
    # the clients were sent each encoding (but the last, for one and for the other)
    assert 8 <= len(images_of_a) <= len(ticks) + 2


@pytest.mark.skipif(os.geteuid() != 0, reason="granting SCHED_FIFO needs root here")
def test_images_are_encoded_in_a_thread_below_a_real_time_tick(tmp_path):
    path = tmp_path / "t.ikg"
    path.write_text(MODEL.replace('name="T"', 'name="T" priority="fifo:30" lock_memory="no"'))
    before = set(threading.enumerate())
    net = ikaros.load(str(path))
    try:
        with TestClient(create_app(net)) as client, client.websocket_connect("/api/ws") as ws:
            ws.send_json({"type": "subscribe", "buffers": [
                {"path": "A.OUTPUT", "format": "jpeg"}]})
            ws.send_json({"type": "ready"})
            _frame(ws)
            encoder, = [t for t in set(threading.enumerate()) - before
                        if t.name.startswith("ikaros-webui-images")]
            tid = encoder.native_id
            assert (os.sched_getscheduler(tid) & ~os.SCHED_RESET_ON_FORK,
                    os.sched_getparam(tid).sched_priority) == \
                (os.SCHED_FIFO, 30 - priority.BELOW_TICK)
    finally:
        net.close()
        priority.reset()


@pytest.mark.skipif(os.geteuid() != 0, reason="granting SCHED_FIFO needs root here")
def test_the_ikaros_command_serves_below_a_real_time_tick(tmp_path):
    path = tmp_path / "t.ikg"
    path.write_text(MODEL.replace('name="T"', 'name="T" priority="fifo:30" lock_memory="no"'))
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen([sys.executable, "-m", "ikaros", "-w", str(port), str(path)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        status = None
        end = time.monotonic() + 30
        while time.monotonic() < end and proc.poll() is None and status is None:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/status",
                                            timeout=2) as r:
                    status = json.load(r)
            except OSError:
                time.sleep(0.1)
        assert status is not None, proc.stderr.read() if proc.poll() is not None else ""
        assert status["priority"]["tick_thread"] == "SCHED_FIFO 30"
        # the server's thread (the encoder's starts with the first image asked for)
        assert status["priority"]["background_threads"] == [
            f"SCHED_FIFO {30 - priority.BELOW_TICK}"]
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
    assert proc.returncode == 0
