"""OutputJPEG: writes images to JPEG files."""
from ikaros.module import Parameter

from ._images import ImageFileWriter


class OutputJPEG(ImageFileWriter):
    """Writes an image to a JPEG file on every tick. The image is INPUT ((rows, cols) gray
    or (3, rows, cols) colour) if it is connected, else INTENSITY (gray), else RED, GREEN
    and BLUE (colour; an unconnected plane is 0). Values are multiplied by ``scale``,
    clipped to 0..1 (with a warning once) and stored as 8-bit levels round(255·v). The file
    name may hold ``%d`` (or ``%02d`` and so on), replaced by the file number: ``offset``
    plus the number of ticks so far, or plus the number of files written with
    ``increase_file_no_on_trig``; without it every tick overwrites the same file. Nothing is
    written on the first ``suppress`` ticks, nor, when WRITE is connected, on ticks when its
    first element is not above 0 (with ``single_trig``, only on ticks when it rises above
    0). A file that cannot be written gives a warning and the run goes on. The Ikaros 2
    class ignored ``scale`` and ``suppress``, took the write signal from INTENSITY instead
    of WRITE, and stretched gray images with values outside 0..1 to their minimum and
    maximum; here both kinds of images are clipped."""

    quality = Parameter(100, "JPEG quality, 1 (smallest file) to 100 (best image)",
                        type="int")
    format_name = "JPEG"
    pillow_format = "JPEG"

    def save_options(self):
        return {"quality": max(1, min(100, self.quality))}
