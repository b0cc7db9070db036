"""InputVideo: a local camera (by index or device path), grabbed in the background."""
from ikaros.module import Parameter

from ._camera import CameraInput, CaptureReader, list_cameras


class InputVideo(CameraInput):
    """Grabs frames from a local camera through OpenCV (V4L2 on Linux, AVFoundation on macOS,
    Media Foundation on Windows), chosen by `id` or by a device path such as /dev/video2.
    Frames are read in a background thread and each tick publishes the newest one, so a tick
    never waits for the camera; FRAME_AGE tells how old the frame is and STALE is set when
    the camera stops delivering. The camera is asked for size_x × size_y at frame_rate;
    frames of another size are scaled to size_x × size_y. `list_devices` prints the cameras
    that can be opened. (Ikaros 2 grabbed with FFmpeg's avdevice; OpenCV's capture does the
    same job. Like any OpenCV capture, `device` also accepts a movie file.)"""

    size_x = Parameter(640, "columns of the output frames", type="int")
    size_y = Parameter(480, "rows of the output frames", type="int")
    frame_rate = Parameter(30.0, "the frame rate asked of the camera")
    id = Parameter(0, "the camera's index (0: the first camera)", type="int")
    device = Parameter("", "a device path (such as /dev/video2) used instead of id")
    list_devices = Parameter(False, "print the camera indices that can be opened")

    reconnect = False

    def source_name(self):
        return f'camera "{self.device}"' if self.device else f"camera {self.id}"

    def open_reader(self):
        return CaptureReader(self.device or self.id, self.size_x, self.size_y,
                             self.frame_rate)

    def configure(self):
        if self.list_devices:
            self.print(f"cameras: {list_cameras()}")
        super().configure()
