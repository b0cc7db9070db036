"""OutputVideoFile: writes one frame per tick to a movie file."""
import logging

from ikaros.module import Parameter, require

from ._files import build_error, resolve
from ._images import ImageInputs, to_uint8

_QUALITY = {"verylow": 2, "low": 4, "normal": 6, "high": 8}   # imageio's 0..10 scale


class OutputVideoFile(ImageInputs):
    """Encodes one frame per tick into a movie file with imageio and its FFmpeg backend
    (H.264 for ``.mp4``; the codec follows the file extension). The frame is INPUT
    ((rows, cols) gray or (3, rows, cols) colour) if it is connected, else INTENSITY (gray),
    else RED, GREEN and BLUE (colour; an unconnected plane is 0), with values in 0..1,
    clipped (with a warning once) and stored as 8-bit levels. ``frame_rate`` is the frame
    rate written in the file; ``quality`` chooses the encoder quality. H.264 needs an even
    width and height, so FFmpeg scales other sizes up to the next even size. The file is
    complete when the run stops. A relative ``filename`` is relative to the model file's
    folder (or to the user-data folder given with ``ikaros -u``)."""

    filename = Parameter("output.mp4", "the movie file to write; relative to the model "
                         "file's folder or the user-data folder (ikaros -u)")
    quality = Parameter("normal", "encoder quality", options="verylow/low/normal/high")
    frame_rate = Parameter(25, "frames per second written in the file", type="int")

    def configure(self):
        self._iio = require("imageio.v3", "imageio", extra="video")
        require("imageio_ffmpeg", "imageio-ffmpeg", extra="video")
        if not self.filename:
            raise build_error(self, "OutputVideoFile needs a filename")
        if self.frame_rate < 1:
            raise build_error(self, "frame_rate must be at least 1")

    def init(self):
        self._writer = self._plugin = None
        self._image = self.image_source()
        path = resolve(self, self.filename, write=True)
        self._plugin = self._iio.imopen(path, "w", plugin="FFMPEG")
        try:
            self._writer = self._plugin.legacy_get_writer(
                fps=self.frame_rate, quality=_QUALITY.get(self.quality, 6),
                macro_block_size=2)
        except Exception:
            self._plugin.close()
            self._plugin = None
            raise

    def tick(self):
        image = self._image()
        self.check_range(image)
        frame = to_uint8(image)
        if frame.ndim == 3:
            frame = frame.transpose(1, 2, 0)
        logger = logging.getLogger("imageio_ffmpeg")
        level = logger.level
        logger.setLevel(logging.ERROR)      # the size warning for odd sizes, once per run
        try:
            self._writer.append_data(frame)
        finally:
            logger.setLevel(level)

    def stop(self):
        if getattr(self, "_writer", None) is not None:
            self._writer.close()
            self._writer = None
        if getattr(self, "_plugin", None) is not None:
            self._plugin.close()
            self._plugin = None
