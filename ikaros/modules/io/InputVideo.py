"""InputVideo: a local camera (by index, name or device path), grabbed in the background."""
import glob
import os

from ikaros.module import Parameter

from ._camera import CameraInput, CaptureReader, list_cameras

VIDEO4LINUX = "/sys/class/video4linux"     # where Linux names its cameras


class InputVideo(CameraInput):
    """Grabs frames from a local camera through OpenCV (V4L2 on Linux, AVFoundation on macOS,
    Media Foundation on Windows), chosen by a device path such as /dev/video2 (`device`), by
    name (`device_name`, Ikaros 3: the first camera whose name contains it; on Linux the
    names of /sys/class/video4linux), or by index (`device_index`, Ikaros 3, when not 0,
    else `id`).
    Frames are read in a background thread and each tick publishes the newest one, so a tick
    never waits for the camera; FRAME_AGE tells how old the frame is and STALE is set when
    the camera stops delivering. The camera is asked for size_x × size_y at frame_rate;
    frames of another size are scaled to size_x × size_y. `list_devices` prints the cameras
    that can be opened. (Ikaros 2 grabbed with FFmpeg's avdevice; OpenCV's capture does the
    same job. Like any OpenCV capture, `device` also accepts a movie file.)"""

    size_x = Parameter(640, "columns of the output frames", type="int", default_v3=1280)
    size_y = Parameter(480, "rows of the output frames", type="int", default_v3=720)
    frame_rate = Parameter(30.0, "the frame rate asked of the camera")
    id = Parameter(0, "the camera's index (0: the first camera)", type="int")
    device = Parameter("", "a device path (such as /dev/video2) used instead of id")
    device_name = Parameter("", "Ikaros 3: the first camera whose name contains this")
    device_index = Parameter(0, "Ikaros 3: the camera's index, used instead of id when not 0",
                             type="int", range=(0, None))
    list_devices = Parameter(False, "print the camera indices that can be opened")

    reconnect = False

    def source_name(self):
        source = self._source
        return f'camera "{source}"' if isinstance(source, str) else f"camera {source}"

    def open_reader(self):
        return CaptureReader(self._source, self.size_x, self.size_y, self.frame_rate)

    def configure(self):
        if self.list_devices:
            self.print(f"cameras: {list_cameras()}")
        self._source = self._camera()
        super().configure()

    def _camera(self) -> str | int:
        """What OpenCV opens: the device path, the camera of that name, or an index."""
        if self.device:
            return self.device
        if self.device_name:
            return camera_named(self.device_name)
        return self.device_index or self.id


def camera_named(name: str, root: str | None = None) -> str:
    """The device path of the first camera (by number) whose name contains ``name``, as
    Linux lists them in /sys/class/video4linux; a ValueError naming the cameras when none
    does."""
    root = root or VIDEO4LINUX
    found = []
    for folder in sorted(glob.glob(os.path.join(root, "video*")),
                         key=lambda f: int(os.path.basename(f)[5:] or 0)):
        try:
            with open(os.path.join(folder, "name"), encoding="utf-8") as f:
                label = f.read().strip()
        except OSError:
            continue
        if name.lower() in label.lower():
            return os.path.join("/dev", os.path.basename(folder))
        found.append(f"{os.path.basename(folder)}: {label}")
    cameras = "; ".join(found) if found else f"none in {root}"
    raise ValueError(f'no camera named "{name}" (cameras: {cameras})')
