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
    every second or so. Frames are scaled to size_x × size_y. With Ikaros 3's
    `synchronized_tick` (its default in a file of dialect 3) each tick waits, at most
    `timeout` seconds, for a frame newer than the one on the outputs, so the model runs at
    the stream's frame rate (or slower); with `synchronized_framegrabber` the grabber reads
    the next frame only when a tick has taken the last, so no frame is skipped (a live
    stream then falls behind when the model is slower than it). (This is this project's
    reading of the two Ikaros 3 parameters, which its reference does not describe.) Ikaros
    2's misspelt `syncronized_framegrabber` and `syncronized_tick`, and `uv4l`, are read
    for compatibility and change nothing: a tick never waits for a frame in an Ikaros 2
    file unless synchronized_tick is set."""

    size_x = Parameter(640, "columns of the output frames", type="int", default_v3=1280)
    size_y = Parameter(480, "rows of the output frames", type="int", default_v3=720)
    url = Parameter("", "the stream's address, e.g. http://camera/video.mjpg or "
                    "rtsp://camera:554/stream")
    info = Parameter(False, "print the stream's address and frame size when it opens")
    syncronized_framegrabber = Parameter(False, "compatibility only: frames are always "
                                         "grabbed in a background thread")
    syncronized_tick = Parameter(True, "compatibility only: a tick never waits for a frame")
    uv4l = Parameter(False, "compatibility only (a UV4L server's MJPEG stream is read like "
                     "any other)")
    synchronized_framegrabber = Parameter(False, "grab the next frame only when a tick has "
                                          "taken the last (no frame is skipped)")
    synchronized_tick = Parameter(False, "each tick waits, at most timeout seconds, for a new "
                                  "frame", default_v3=True)

    def waits_for_frames(self):
        return self.synchronized_tick

    def paces_the_grabber(self):
        return self.synchronized_framegrabber

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
