"""TheEyeTribe: gaze, fixation and pupils from an Eye Tribe eye tracker."""
from ikaros.module import Module, Output, Parameter


def _point(d, key):
    p = d.get(key) or {}
    return float(p.get("x", 0.0)), float(p.get("y", 0.0))


class TheEyeTribe(Module):
    """Reads an Eye Tribe tracker through its server's documented API (JSON over TCP,
    port 6555): asks it to push frames, sends the heartbeat it expects every 250 ms, and
    every tick shows the newest frame (the outputs keep their values until a new one
    comes). Gaze points are in screen pixels; pupil centres are 0..1 of the camera image;
    TIME_STAMP is the frame's ``time`` (milliseconds). A server that cannot be reached at
    load is a load error; one lost later is reported as a warning and retried every second
    while the run goes on. A message that is not JSON is skipped with a warning naming it, and
    reading goes on with the next one. Unlike Ikaros 2, which linked the tracker's C++ SDK, no SDK is
    needed, and the server may be on another machine (``host``)."""

    host = Parameter("127.0.0.1", "the address of the Eye Tribe server")
    port = Parameter(6555, "its TCP port", type="int")

    TIME_STAMP = Output("the frame's time stamp, in milliseconds", size=1)
    FIX = Output("1 while the gaze is fixated, else 0", size=1)
    RAW = Output("the raw gaze point (x, y), in pixels", size=2)
    AVG = Output("the smoothed gaze point (x, y), in pixels", size=2)
    LEFT_EYE_RAW = Output("the left eye's raw gaze point (x, y)", size=2)
    LEFT_AVG_RAW = Output("the left eye's smoothed gaze point (x, y)", size=2)
    LEFT_PUPIL_SIZE = Output("the left pupil's size", size=1)
    LEFT_PUPIL_CENTER = Output("the left pupil's centre (x, y), 0..1", size=2)
    RIGHT_EYE_RAW = Output("the right eye's raw gaze point (x, y)", size=2)
    RIGHT_AVG_RAW = Output("the right eye's smoothed gaze point (x, y)", size=2)
    RIGHT_PUPIL_SIZE = Output("the right pupil's size", size=1)
    RIGHT_PUPIL_CENTER = Output("the right pupil's centre (x, y), 0..1", size=2)

    def init(self):
        from ikaros.hardware.eyetribe import EyeTribeClient
        try:
            self._client = EyeTribeClient(self.host, self.port)
        except OSError as e:
            raise ValueError(f"cannot reach the Eye Tribe server at {self.host}:{self.port} "
                             f"({e}); is EyeTribe Server running?") from None
        self._seen = 0
        self._error = None

    def tick(self):
        error = self._client.error
        if error != self._error:
            if error:
                self.warning(f"lost the Eye Tribe server at {self.host}:{self.port} "
                             f"({error}); retrying")
            else:
                self.print(f"the Eye Tribe server at {self.host}:{self.port} is back")
            self._error = error
        for text in self._client.take_skipped():
            self.warning(f"skipped a message from the Eye Tribe server at {self.host}:{self.port} "
                         f"that is not JSON: {text[:80]!r}")
        frame, count = self._client.newest()
        if frame is None or count == self._seen:
            return
        self._seen = count
        self.TIME_STAMP[0] = float(frame.get("time", 0))
        self.FIX[0] = bool(frame.get("fix"))
        self.RAW[:] = _point(frame, "raw")
        self.AVG[:] = _point(frame, "avg")
        for side, raw, avg, size, centre in (
                ("lefteye", self.LEFT_EYE_RAW, self.LEFT_AVG_RAW, self.LEFT_PUPIL_SIZE,
                 self.LEFT_PUPIL_CENTER),
                ("righteye", self.RIGHT_EYE_RAW, self.RIGHT_AVG_RAW, self.RIGHT_PUPIL_SIZE,
                 self.RIGHT_PUPIL_CENTER)):
            eye = frame.get(side) or {}
            raw[:] = _point(eye, "raw")
            avg[:] = _point(eye, "avg")
            size[0] = float(eye.get("psize", 0.0))
            centre[:] = _point(eye, "pcenter")

    def stop(self):
        self._client.close()
