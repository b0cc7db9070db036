"""InputVideoStream: a network video stream (HTTP MJPEG, RTSP, ...), grabbed in the
background."""
from ikaros.module import Parameter

from ._camera import CameraInput, open_stream


class InputVideoStream(CameraInput):
    """Reads a network video stream given by `url`: http:// and https:// MJPEG streams (and
    JPEG snapshot URLs, polled) with a small reader whose every read has a time-out, and
    rtsp:// and any other URL FFmpeg reads through OpenCV's capture. Frames are grabbed in a
    background thread and each tick publishes the newest one; FRAME_AGE is its age and STALE
    is set when no frame came for `timeout` seconds. A stream that stops is opened again
    every second or so. Frames are scaled to size_x × size_y. `syncronized_framegrabber`,
    `syncronized_tick` and `uv4l` are read for compatibility: here the grab is always in its
    own thread and a tick never waits for a frame (Ikaros 2 could wait for the next frame)."""

    size_x = Parameter(640, "columns of the output frames", type="int")
    size_y = Parameter(480, "rows of the output frames", type="int")
    url = Parameter("", "the stream's address, e.g. http://camera/video.mjpg or "
                    "rtsp://camera:554/stream")
    info = Parameter(False, "print the stream's address and frame size when it opens")
    syncronized_framegrabber = Parameter(False, "compatibility only: frames are always "
                                         "grabbed in a background thread")
    syncronized_tick = Parameter(True, "compatibility only: a tick never waits for a frame")
    uv4l = Parameter(False, "compatibility only (a UV4L server's MJPEG stream is read like "
                     "any other)")

    def source_name(self):
        return f'stream "{self.url}"'

    def open_reader(self):
        return open_stream(self.url, self.timeout)

    def configure(self):
        if not self.url:
            raise ValueError(f"{type(self).__name__} needs a url")
        super().configure()
        if self.info:
            self.print(f"{self.source_name()}: {self.output_shape('RED')[1]} x "
                       f"{self.output_shape('RED')[0]}")
