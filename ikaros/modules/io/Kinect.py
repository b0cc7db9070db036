"""Kinect: a depth camera (Kinect or Xtion), or an RGB-D recording in its place."""
import threading

import numpy as np

from ikaros.module import Input, MissingDependency, device_thread, Module, Output, Parameter

from ._files import resolve
from ikaros.hardware.rgbd_recording import mm_to_raw, raw_to_mm


class Kinect(Module):
    """Depth and colour images from a Microsoft Kinect (through libfreenect's Python
    bindings, the `freenect` module) or, with `xtion`, an Asus Xtion (through OpenNI 2's
    Python bindings, `openni`), or from an RGB-D `recording` (see
    ikaros.hardware.rgbd_recording) played one frame per tick (tick k shows frame k, init
    frame 0), over and over, so that depth models run without the device. DEPTH is the raw
    11-bit reading scaled to 0..1 (raw / 2047) with mode raw, or the depth in mm with mode
    mm (0 where there is no reading). OUTPUT is the colour image and RED, GREEN, BLUE and
    INTENSITY its planes and their mean. A device is read in a background thread and each
    tick publishes the newest frames. The outputs have the frames' size (640 × 480 for the
    devices). When the library for the device is missing the model does not load, and the
    error names the library. TILT (degrees) and LED (0..6) are sent to a Kinect when they
    change."""

    mode = Parameter("raw", "raw: DEPTH is raw / 2047; mm: DEPTH is in millimetres",
                     options="raw/mm")
    xtion = Parameter(False, "the camera is an Asus Xtion (OpenNI 2) rather than a Kinect")
    index = Parameter(0, "which camera, when there are several", type="int")
    recording = Parameter("", "an RGB-D recording (.npz) to play instead of a camera; "
                          "relative to the model file's folder")
    TILT = Input("the tilt of the Kinect's motor, degrees", optional=True)
    LED = Input("the Kinect's LED: 0 off, 1 green, 2 red, 3 yellow, 4 blinking", optional=True)
    DEPTH = Output("the depth image: raw / 2047, or mm")
    OUTPUT = Output("the colour image (3, rows, cols) in 0..1")
    RED = Output("the red plane")
    GREEN = Output("the green plane")
    BLUE = Output("the blue plane")
    INTENSITY = Output("the mean of red, green and blue")

    def configure(self):
        if self.recording:
            path = resolve(self, self.recording)
            try:
                with np.load(path) as data:
                    self._rgb, self._raw = data["rgb"], data["depth"]
            except (OSError, KeyError, ValueError) as e:
                raise OSError(f'cannot read RGB-D recording "{path}": {e}') from None
            if self._rgb.ndim != 4 or self._raw.shape != self._rgb.shape[:3]:
                raise ValueError(f'RGB-D recording "{path}" needs rgb (frames, rows, '
                                  f'cols, 3) and depth (frames, rows, cols)')
            shape = self._raw.shape[1:]
            self._device = None
        else:
            self._device = self._open_device()
            shape = (480, 640)
        self.set_output_shape("OUTPUT", (3,) + tuple(shape))
        for name in ("DEPTH", "RED", "GREEN", "BLUE", "INTENSITY"):
            self.set_output_shape(name, shape)

    def _open_device(self):
        import importlib
        if self.xtion:
            try:
                openni2 = importlib.import_module("openni.openni2")
            except ImportError:
                raise MissingDependency("Kinect with xtion needs OpenNI 2 and its Python "
                                  "bindings (pip install openni, and the OpenNI 2 runtime); "
                                  "or set recording= to play an RGB-D recording") from None
            try:
                return XtionReader(openni2, self.index)
            except Exception as e:
                raise OSError(f"cannot open Xtion {self.index}: {e}") from None
        try:
            freenect = importlib.import_module("freenect")
        except ImportError:
            raise MissingDependency("Kinect needs libfreenect and its Python bindings (the "
                              "freenect module, built with libfreenect's wrappers/python); "
                              "or set recording= to play an RGB-D recording") from None
        try:
            return KinectReader(freenect, self.index)
        except OSError as e:
            raise OSError(f"cannot open Kinect {self.index}: {e}") from None

    def init(self):
        self._show(*self._next())

    def _next(self):
        if self._device is None:
            k = max(0, self.clock.tick) % len(self._raw)
            return self._rgb[k], self._raw[k]
        return self._device.latest()

    def _show(self, rgb, raw):
        np.multiply(rgb.transpose(2, 0, 1), np.float32(1 / 255), out=self.OUTPUT)
        self.RED[...], self.GREEN[...], self.BLUE[...] = self.OUTPUT
        np.mean(self.OUTPUT, axis=0, out=self.INTENSITY)
        if self.mode == "mm":
            self.DEPTH[...] = raw_to_mm(raw)
        else:
            np.multiply(raw, np.float32(1 / 2047), out=self.DEPTH)

    def tick(self):
        if self._device is not None:
            self._device.control(self.TILT, self.LED)
        self._show(*self._next())

    def stop(self):
        if getattr(self, "_device", None) is not None:
            self._device.close()


class DeviceReader:
    """Grabs (rgb, raw depth) pairs from a device in a background thread; ``latest`` gives
    the newest at once."""

    def __init__(self):
        self._latest = self.grab()
        if self._latest is None:
            raise OSError("the camera sends no frames")
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._thread = threading.Thread(target=self._run, daemon=True, name="ikaros-rgbd")
        self._thread.start()

    def grab(self):
        """The next (rgb uint8 (rows, cols, 3), raw depth (rows, cols)), or None."""
        raise NotImplementedError

    def _run(self):
        device_thread()
        while not self._stop.is_set():
            frames = self.grab()
            if frames is None:
                self._stop.wait(0.05)
                continue
            with self._lock:
                self._latest = frames

    def latest(self):
        with self._lock:
            return self._latest

    def control(self, tilt, led):
        """Send TILT and LED to the device when they change (only a Kinect has them)."""

    def close(self):
        self._stop.set()
        self._thread.join(timeout=2)


class KinectReader(DeviceReader):
    """A Kinect through freenect's synchronous API."""

    def __init__(self, freenect, index):
        self.freenect, self.index = freenect, index
        self._sent = (None, None)
        super().__init__()

    def grab(self):
        depth = self.freenect.sync_get_depth(self.index)
        video = self.freenect.sync_get_video(self.index)
        return None if depth is None or video is None else (video[0], depth[0])

    def control(self, tilt, led):
        wanted = (None if tilt is None else float(tilt.flat[0]),
                  None if led is None else int(led.flat[0]))
        if wanted == self._sent:
            return
        self._sent = wanted
        if wanted[0] is not None and hasattr(self.freenect, "sync_set_tilt_degs"):
            self.freenect.sync_set_tilt_degs(wanted[0], self.index)
        if wanted[1] is not None and hasattr(self.freenect, "sync_set_led"):
            self.freenect.sync_set_led(wanted[1], self.index)

    def close(self):
        super().close()
        self.freenect.sync_stop()


class XtionReader(DeviceReader):
    """An Asus Xtion through OpenNI 2; its depth in mm becomes Kinect raw values so that
    both cameras give the same DEPTH."""

    def __init__(self, openni2, index):
        openni2.initialize()
        devices = openni2.Device.open_all()
        if index >= len(devices):
            raise OSError(f"no Xtion {index}")
        self.depth = devices[index].create_depth_stream()
        self.colour = devices[index].create_color_stream()
        self.depth.start()
        self.colour.start()
        super().__init__()

    def grab(self):
        d, c = self.depth.read_frame(), self.colour.read_frame()
        mm = np.frombuffer(d.get_buffer_as_uint16(), np.uint16).reshape(d.height, d.width)
        rgb = np.frombuffer(c.get_buffer_as_uint8(), np.uint8).reshape(c.height, c.width, 3)
        return rgb, mm_to_raw(mm)

    def close(self):
        super().close()
        self.depth.stop()
        self.colour.stop()
