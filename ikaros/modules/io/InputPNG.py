"""InputPNG: reads a PNG image or a numbered sequence of PNG images."""
from ikaros.module import Parameter

from ._images import ImageFileReader


class InputPNG(ImageFileReader):
    """Reads a PNG file (gray or colour, 8 or 16 bits; an alpha channel is ignored), or a
    numbered sequence of them (a ``%d`` in ``filename``, ``filecount`` files), and outputs
    it with values in 0..1: OUTPUT is the colour image (3, rows, cols), RED, GREEN and BLUE
    its planes and INTENSITY the mean of the three (a gray file gives three equal planes).
    The size is ``size_x`` × ``size_y`` when both are set (files of another size are resized
    to it), otherwise the size of the first file. The first image is on the outputs from
    init; on tick k the sequence shows file k modulo ``filecount``, and after ``iterations``
    passes (0 means forever) the module sends end-of-file, which stops the run, and keeps
    the last image. A file that cannot be read gives a warning and the previous image stays.
    Each file is read when the sequence moves to it. The file is decoded by Pillow, which
    also reads other formats."""

    size_x = Parameter(None, "columns of the output image; unset: the width of the first "
                       "file", type="int")
    size_y = Parameter(None, "rows of the output image; unset: the height of the first file",
                       type="int")
    notify_repeat = Parameter(False, "print a message each time the sequence starts over")
    format_name = "PNG"

    def requested_shape(self):
        if self.size_x and self.size_y and self.size_x > 0 and self.size_y > 0:
            return (self.size_y, self.size_x)
        return None

    def notify_repeat_enabled(self):
        return self.notify_repeat
