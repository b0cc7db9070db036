"""OutputPNG: writes images to PNG files."""
from ._images import ImageFileWriter


class OutputPNG(ImageFileWriter):
    """Writes an image to an 8-bit PNG file on every tick (PNG is lossless, so reading the
    file back gives the same 8-bit levels). The image is INPUT ((rows, cols) gray or
    (3, rows, cols) colour) if it is connected, else INTENSITY (gray), else RED, GREEN and
    BLUE (colour; an unconnected plane is 0). Values are multiplied by ``scale``, clipped
    to 0..1 (with a warning once) and stored as round(255·v). The file name may hold ``%d``
    (or ``%02d`` and so on), replaced by the file number: ``offset`` plus the number of
    ticks so far, or plus the number of files written with ``increase_file_no_on_trig``;
    without it every tick overwrites the same file, which then holds the last image.
    Nothing is written on the first ``suppress`` ticks, nor, when WRITE is connected, on
    ticks when its first element is not above 0 (with ``single_trig``, only on ticks when it
    rises above 0). A file that cannot be written gives a warning and the run goes on."""

    format_name = "PNG"
    pillow_format = "PNG"
