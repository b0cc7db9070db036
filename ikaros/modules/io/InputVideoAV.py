"""InputVideoAV: a camera, a movie file or a stream through OpenCV's video backend."""
from ikaros.module import Parameter

from ._camera import CameraInput, CaptureReader, list_cameras, open_stream
from ._files import resolve


class InputVideoAV(CameraInput):
    """Reads a camera (`device_id`, an index or a device path), a movie file (`filename`,
    played at its own frame rate) or a stream (`url`) through OpenCV's video backend
    (FFmpeg, V4L2, AVFoundation). Frames are grabbed in a background thread and each tick
    publishes the newest one, scaled to size_x × size_y and mirrored left-right with `flip`;
    FRAME_AGE is its age and STALE is set when no frame came for `timeout` seconds. At the
    end of a file the module sends end-of-file, which stops the run. (Ikaros 2's class read
    cameras only, on macOS with AVFoundation; `mode` is read for compatibility and preview
    mode is not different here.)"""

    size_x = Parameter(1920, "columns of the output frames", type="int")
    size_y = Parameter(1080, "rows of the output frames", type="int")
    flip = Parameter(False, "mirror the frames left-right")
    mode = Parameter("standard", "compatibility only: the capture mode of Ikaros 2",
                     options="standard/preview")
    device_id = Parameter("", "a camera: its index (0 is the first) or device path; used "
                          "when neither filename nor url is set (then camera 0)")
    filename = Parameter("", "a movie file, relative to the model file's folder")
    url = Parameter("", "a stream address (rtsp://, http:// MJPEG, ...)")
    list_devices = Parameter(False, "print the camera indices that can be opened")

    @property
    def flip_frames(self):
        return self.flip

    @property
    def reconnect(self):
        return bool(self.url)

    @property
    def end_of_source(self):
        return bool(self.filename)

    def _camera(self):
        d = str(self.device_id).strip()
        return int(d) if d.lstrip("-").isdigit() else (d or 0)

    def source_name(self):
        if self.filename:
            return f'movie file "{resolve(self, self.filename)}"'
        if self.url:
            return f'stream "{self.url}"'
        return f'camera "{self._camera()}"'

    def open_reader(self):
        if self.filename:
            return CaptureReader(resolve(self, self.filename), paced=True)
        if self.url:
            return open_stream(self.url, self.timeout)
        return CaptureReader(self._camera(), self.size_x, self.size_y)

    def configure(self):
        if self.list_devices:
            self.print(f"cameras: {list_cameras()}")
        super().configure()
