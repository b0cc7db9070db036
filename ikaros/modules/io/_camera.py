"""The base of the camera and stream inputs: frames are grabbed in a background thread, and
each tick publishes the newest one, so a slow or stopped camera never holds up a tick."""
from __future__ import annotations

import threading
import time
from typing import Callable

import numpy as np

from ikaros.module import Module, Output, Parameter, device_thread, require


class CaptureReader:
    """A cv2.VideoCapture (camera index, device path, file or stream URL) as RGB frames."""

    def __init__(self, source, width: int | None = None, height: int | None = None,
                 fps: float | None = None, paced: bool = False):
        cv2 = self.cv2 = require("cv2", "opencv-python-headless", extra="vision")
        logging = cv2.utils.logging           # the failed tries of other backends are noise
        level = logging.getLogLevel()
        logging.setLogLevel(logging.LOG_LEVEL_ERROR)
        try:
            self.capture = cv2.VideoCapture(source)
        finally:
            logging.setLogLevel(level)
        if not self.capture.isOpened():
            raise OSError("no such camera or file, it is in use, or OpenCV cannot read it")
        if width:
            self.capture.set(cv2.CAP_PROP_FRAME_WIDTH, width)
        if height:
            self.capture.set(cv2.CAP_PROP_FRAME_HEIGHT, height)
        if fps:
            self.capture.set(cv2.CAP_PROP_FPS, fps)
        # a file is played at its own frame rate, as a camera would deliver it
        rate = self.capture.get(cv2.CAP_PROP_FPS) if paced else 0
        self.interval = 1.0 / rate if rate and rate > 0 else 0.0
        self._due = time.monotonic()

    def read(self) -> np.ndarray | None:
        ok, bgr = self.capture.read()
        if self.interval:
            self._due += self.interval
            time.sleep(max(0.0, self._due - time.monotonic()))
        return bgr[:, :, ::-1] if ok else None

    def close(self):
        self.capture.release()


class FrameGrabber:
    """Reads frames in a daemon thread and keeps the newest, converted to four float32
    planes (red, green, blue, intensity) in 0..1 at the output size. The reader is used and
    closed in that thread only (OpenCV's capture must not be released during a read).

    ``open_reader()`` makes a reader (``read() -> RGB uint8 or None``, ``close()``). When it
    returns None the source ended: with ``reconnect`` the grabber opens it again after
    ``retry`` seconds, otherwise it stops and ``ended`` is set.
    """

    def __init__(self, open_reader: Callable, reconnect: bool, retry: float = 1.0,
                 name: str = "camera", paced: bool = False):
        self.cv2 = require("cv2", "opencv-python-headless", extra="vision")
        self.open_reader, self.reconnect, self.retry = open_reader, reconnect, retry
        self.size: tuple[int, int] | None = None     # (rows, cols) of the planes
        self.flip = False
        # paced: after each frame the grabber waits until a tick has taken it
        self.paced = paced
        self._taken = threading.Event()
        self._lock = threading.Lock()
        self._new_frame = threading.Condition(self._lock)
        self._frame: np.ndarray | None = None
        self._time = 0.0
        self.count = 0
        self.ended = threading.Event()
        self._stopping = threading.Event()
        self._first = threading.Event()
        self._sized = threading.Event()
        self.error: str | None = None                # why the last reconnection failed
        self.reader = open_reader()
        self._thread = threading.Thread(target=self._run, daemon=True,
                                        name=f"ikaros-grab-{name}")
        self._thread.start()

    def wait_first(self, timeout: float) -> np.ndarray | None:
        """The first raw frame (RGB uint8), or None if none came within timeout seconds."""
        self._first.wait(timeout)
        return self._raw_first

    _raw_first = None

    def _planes(self, rgb: np.ndarray) -> np.ndarray:
        cv2 = self.cv2
        rows, cols = self.size or rgb.shape[:2]
        if rgb.shape[:2] != (rows, cols):
            rgb = cv2.resize(rgb, (cols, rows), interpolation=cv2.INTER_AREA)
        if self.flip:
            rgb = rgb[:, ::-1]
        planes = np.empty((4, rows, cols), np.float32)
        np.multiply(rgb.transpose(2, 0, 1), np.float32(1 / 255), out=planes[:3])
        np.mean(planes[:3], axis=0, out=planes[3])
        return planes

    def _run(self):
        device_thread()
        try:
            self._grab()
        finally:
            if self.reader is not None:       # the reader is closed in this thread only
                self.reader.close()
                self.reader = None

    def _grab(self):
        while not self._stopping.is_set():
            rgb = self.reader.read() if self.reader is not None else None
            if self._stopping.is_set():
                return
            if rgb is None:
                if self.reader is not None:
                    self.reader.close()
                    self.reader = None
                if not self.reconnect:
                    self.ended.set()
                    return
                if self._stopping.wait(self.retry):
                    return
                try:
                    self.reader = self.open_reader()
                    self.error = None
                except OSError as e:
                    self.error = str(e)
                continue
            if not self._first.is_set():
                self._raw_first = rgb
                self._first.set()
                while not self._sized.wait(0.05):   # the owner sets the size now
                    if self._stopping.is_set():
                        return
                continue
            planes = self._planes(rgb)
            with self._lock:
                self._frame, self._time = planes, time.monotonic()
                self.count += 1
                self._taken.clear()
                self._new_frame.notify_all()
            while self.paced and not self._taken.wait(0.05):
                if self._stopping.is_set():
                    return

    def latest(self) -> tuple[np.ndarray | None, float, int]:
        """The newest frame's planes, its time (time.monotonic) and its number."""
        with self._lock:
            self._taken.set()
            return self._frame, self._time, self.count

    def wait_newer(self, count: int, timeout: float) -> None:
        """Wait (at most ``timeout`` seconds) until a frame newer than number ``count`` has
        been grabbed."""
        with self._new_frame:
            self._new_frame.wait_for(lambda: self.count > count or self.ended.is_set(),
                                     timeout)

    def start_publishing(self, size: tuple[int, int], flip: bool, first: np.ndarray):
        """Set the output size (rows, cols) and publish the first frame."""
        self.size, self.flip = tuple(size), flip
        self._sized.set()
        with self._lock:
            if self._frame is None:
                self._frame, self._time = self._planes(first), time.monotonic()
                self.count += 1

    def stop(self):
        """Stop grabbing. A reader that can be interrupted (a network stream) is, so that a
        read waiting on the source returns; others finish their read within a frame."""
        self._stopping.set()
        interrupt = getattr(self.reader, "interrupt", None)
        if interrupt is not None:
            interrupt()
        self._thread.join(timeout=3.0)


class CameraInput(Module):
    """Base of the camera and stream inputs. Subclasses give ``source_name()``,
    ``open_reader()``, ``reconnect`` and the sizes they ask for."""

    OUTPUT = Output("the newest colour frame, (3, rows, cols): planes red, green and blue in "
                    "0..1")
    RED = Output("the red plane of the frame (rows, cols)")
    GREEN = Output("the green plane of the frame (rows, cols)")
    BLUE = Output("the blue plane of the frame (rows, cols)")
    INTENSITY = Output("the intensity of the frame (rows, cols): the mean of red, green and "
                       "blue")
    FRAME_AGE = Output("seconds since the frame on the outputs was grabbed", size="1")
    STALE = Output("1 when no new frame has come for `timeout` seconds (the camera or stream "
                   "stopped), otherwise 0", size="1")

    timeout = Parameter(2.0, "seconds to wait for the first frame when the model loads, and "
                        "without a new frame before STALE is set")

    reconnect = True          # a stream that stops is opened again
    end_of_source = False     # the source ending ends the run (files)
    flip_frames = False

    def waits_for_frames(self) -> bool:
        """Whether a tick waits (at most ``timeout``) for a frame newer than the last."""
        return False

    def paces_the_grabber(self) -> bool:
        """Whether the grabber reads a frame only after a tick has taken the last."""
        return False

    def source_name(self) -> str:
        raise NotImplementedError

    def open_reader(self):
        raise NotImplementedError

    def requested_size(self) -> tuple[int, int] | None:
        """(rows, cols) of the outputs, or None for the size of the frames."""
        sx, sy = getattr(self, "size_x", None), getattr(self, "size_y", None)
        return (int(sy), int(sx)) if sx and sy and sx > 0 and sy > 0 else None

    def configure(self):
        require("cv2", "opencv-python-headless", extra="vision")
        try:
            self._grabber = FrameGrabber(self.open_reader, self.reconnect,
                                         retry=min(1.0, self.timeout), name=self.name,
                                         paced=self.paces_the_grabber())
        except OSError as e:
            raise OSError(f"cannot open {self.source_name()}: {e}") from None
        first = self._grabber.wait_first(self.timeout)
        if first is None:
            self._grabber.stop()
            raise OSError(f"no frame from {self.source_name()} within {self.timeout:g} s")
        size = self.requested_size() or first.shape[:2]
        self._grabber.start_publishing(size, self.flip_frames, first)
        self.set_output_shape("OUTPUT", (3,) + tuple(size))
        for name in ("RED", "GREEN", "BLUE", "INTENSITY"):
            self.set_output_shape(name, size)

    def init(self):
        self._shown = -1
        self._stale_reported = False
        self._publish()

    def _publish(self):
        planes, grabbed, count = self._grabber.latest()
        if count != self._shown and planes is not None:
            self._shown = count
            self.OUTPUT[...] = planes[:3]
            self.RED[...] = planes[0]
            self.GREEN[...] = planes[1]
            self.BLUE[...] = planes[2]
            self.INTENSITY[...] = planes[3]
        age = time.monotonic() - grabbed
        self.FRAME_AGE[0] = age
        stale = age > self.timeout or (self._grabber.ended.is_set() and not self.end_of_source)
        self.STALE[0] = float(stale)
        if stale and not self._stale_reported:
            self._stale_reported = True
            reason = f" (reconnecting: {self._grabber.error})" if self._grabber.error else ""
            self.warning(f"no new frame from {self.source_name()} for {age:.1f} s{reason}; "
                         f"the last frame is kept and STALE is 1")
        elif not stale:
            self._stale_reported = False

    def tick(self):
        if self.waits_for_frames():
            self._grabber.wait_newer(self._shown, self.timeout)
        self._publish()
        if self.end_of_source and self._grabber.ended.is_set() and \
                self._grabber.latest()[2] == self._shown:
            self.end_of_file(f"end of {self.source_name()}")

    def stop(self):
        grabber = getattr(self, "_grabber", None)
        if grabber is not None:
            grabber.stop()


def open_stream(url: str, timeout: float):
    """A reader for a stream URL: HTTP MJPEG (or JPEG snapshots) with the MJPEG reader, any
    other URL (rtsp://, HLS, ...) with cv2.VideoCapture and its FFmpeg backend."""
    if url.startswith(("http://", "https://")):
        from ikaros.hardware.mjpeg import MJPEGReader, NotMJPEG
        try:
            return MJPEGReader(url, timeout)
        except NotMJPEG:
            pass
    return CaptureReader(url)


def list_cameras(count: int = 8) -> str:
    """The indices of the cameras among the first ``count`` that OpenCV can open."""
    found = []
    for index in range(count):
        try:
            CaptureReader(index).close()
        except OSError:
            continue
        found.append(str(index))
    return ", ".join(found) or "none found"
