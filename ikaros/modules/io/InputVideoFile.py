"""InputVideoFile: reads the frames of a movie file, one per tick."""
import logging
import os

import numpy as np

from ikaros.module import Module, Output, Parameter, require

from ._files import build_error, resolve
from ._images import from_uint8


class InputVideoFile(Module):
    """Decodes a movie file (any format FFmpeg reads: MP4, MOV, AVI, ...) with imageio and
    its FFmpeg backend, and outputs one frame per tick with values in 0..1: OUTPUT is the
    colour frame (3, rows, cols), RED, GREEN and BLUE its planes and INTENSITY the mean of
    the three. Frames are not timed: frame k is output on tick k whatever the movie's frame
    rate. The first frame is on the outputs from init, and RESTART is 1 on the ticks that
    show the first frame (tick 0 and, with ``loop``, each restart) and 0 otherwise. With
    ``size_x`` and ``size_y`` FFmpeg scales the frames to that size; with only one of them
    the other follows the movie's aspect ratio. After the last frame the movie starts over
    when ``loop`` is set; otherwise the module sends end-of-file on the tick of the last
    frame, which stops the run. ``info`` prints the codec, size, frame rate and duration."""

    filename = Parameter("", "the movie file; relative to the model file's folder")
    size_x = Parameter(None, "columns of the output frames; unset: the movie's width (or "
                       "the aspect ratio with size_y)", type="int")
    size_y = Parameter(None, "rows of the output frames; unset: the movie's height (or the "
                       "aspect ratio with size_x)", type="int")
    loop = Parameter(False, "start the movie over after its last frame instead of sending "
                     "end-of-file")
    info = Parameter(False, "print information about the movie when the run starts")

    OUTPUT = Output("the colour frame, (3, rows, cols): planes red, green and blue in 0..1")
    RED = Output("the red plane of the frame (rows, cols)")
    GREEN = Output("the green plane of the frame (rows, cols)")
    BLUE = Output("the blue plane of the frame (rows, cols)")
    INTENSITY = Output("the intensity of the frame (rows, cols): the mean of red, green and "
                       "blue")
    RESTART = Output("1 on a tick that shows the first frame of the movie, otherwise 0",
                     size="1")

    def configure(self):
        self._iio = require("imageio.v3", "imageio", extra="video")
        require("imageio_ffmpeg", "imageio-ffmpeg", extra="video")
        if not self.filename:
            raise build_error(self, "InputVideoFile needs a filename")
        self._path = resolve(self, self.filename)
        if not os.path.isfile(self._path):
            raise build_error(self, f'cannot read movie file "{self._path}": no such file')
        try:
            reader, plugin = self._open(None)
            try:
                self._meta = reader.get_meta_data()
                first = reader.get_next_data()
            finally:
                reader.close()
                plugin.close()
        except IndexError:
            raise build_error(self, f'movie file "{self._path}" has no frames') from None
        except Exception as e:
            raise build_error(self, f'cannot read movie file "{self._path}": '
                              f'{type(e).__name__}: {e}') from None
        rows, cols = first.shape[:2]
        sx = self.size_x if self.size_x and self.size_x > 0 else None
        sy = self.size_y if self.size_y and self.size_y > 0 else None
        if sx and not sy:
            sy = max(1, round(sx * rows / cols))
        elif sy and not sx:
            sx = max(1, round(sy * cols / rows))
        self._size = (sx, sy) if sx else None
        shape = (sy, sx) if sx else (rows, cols)
        self.set_output_shape("OUTPUT", (3,) + shape)
        for name in ("RED", "GREEN", "BLUE", "INTENSITY"):
            self.set_output_shape(name, shape)

    def _open(self, size):
        plugin = self._iio.imopen(self._path, "r", plugin="FFMPEG")
        # imageio_ffmpeg logs a warning whenever frames are scaled; scaling is asked for here
        logger = logging.getLogger("imageio_ffmpeg")
        level = logger.level
        logger.setLevel(logging.ERROR)
        try:
            reader = plugin.legacy_get_reader(**({"size": size} if size else {}))
        except Exception:
            plugin.close()
            raise
        finally:
            logger.setLevel(level)
        return reader, plugin

    def _start(self):
        """Open the movie and fetch its first frame as the pending one."""
        self._close()
        self._reader, self._plugin = self._open(self._size)
        self._frame_number = 0
        self._pending = self._fetch()

    def _fetch(self):
        try:
            frame = self._reader.get_next_data()
        except IndexError:
            return None
        return from_uint8(np.asarray(frame)[..., :3]).transpose(2, 0, 1)

    def init(self):
        self._reader = self._plugin = None
        self._done = False
        if self.info:
            m = self._meta
            self.print(f'"{self._path}": codec {m.get("codec")}, size {m.get("source_size")}, '
                       f'{m.get("fps")} frames/s, {m.get("duration")} s')
        self._start()
        if self._pending is None:
            raise ValueError(f'movie file "{self._path}" has no frames')
        self._show(self._pending)
        self.RESTART.fill(0)
        self._first_pending = True         # the pending frame is the movie's first

    def _show(self, frame):
        self.OUTPUT[...] = frame
        self.RED[...] = frame[0]
        self.GREEN[...] = frame[1]
        self.BLUE[...] = frame[2]
        np.mean(frame, axis=0, out=self.INTENSITY)

    def tick(self):
        if self._done:
            self.RESTART.fill(0)
            return
        if self._pending is None:          # the movie ended on the previous tick: loop
            self._start()
            self._first_pending = True
            if self._pending is None:
                self._done = True
                return
        self._show(self._pending)
        self.RESTART.fill(1.0 if self._first_pending else 0.0)
        self._first_pending = False
        self._pending = self._fetch()
        if self._pending is None and not self.loop:
            self._done = True
            self._close()
            self.end_of_file(f'end of movie "{self.filename}"')

    def _close(self):
        if getattr(self, "_reader", None) is not None:
            self._reader.close()
            self._plugin.close()
            self._reader = self._plugin = None

    def stop(self):
        self._close()
