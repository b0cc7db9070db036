"""InputJPEG: reads a JPEG image or a numbered sequence of JPEG images."""
from ._images import ReadOnce


class InputJPEG(ReadOnce):
    """Reads a JPEG file, gray or colour, or a numbered sequence of them (a ``%d`` in
    ``filename``, ``filecount`` files), and outputs it with values in 0..1: OUTPUT is the
    colour image (3, rows, cols), RED, GREEN and BLUE its planes and INTENSITY the mean of
    the three (a gray file gives three equal planes). The size comes from the first file;
    later files of another size are resized to it. The first image is on the outputs from
    init; on tick k the sequence shows file k modulo ``filecount``, and after ``iterations``
    passes (0 means forever) the module sends end-of-file, which stops the run, and keeps
    the last image. A file that cannot be read gives a warning and the previous image stays.
    With ``read_once`` (the default) a file is read only when the sequence moves to it, so
    a single image is read once; with read_once=no the current file is read again on every
    tick, which shows changes made by another program. The file is decoded by Pillow, which
    also reads other formats. The Ikaros 2 class computed INTENSITY incorrectly; here it is
    the plain mean of red, green and blue."""

    format_name = "JPEG"
