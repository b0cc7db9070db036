"""InputImage: the Ikaros 3 image reader (JPEG, PNG and the other formats Pillow reads)."""
from ._files import build_error, counter_capacity
from ._images import ReadOnce
from .InputPNG import InputPNG


class InputImage(InputPNG, ReadOnce):
    """Ikaros 3's name for the image readers (Ikaros 2: InputJPEG, InputPNG). Reads a JPEG,
    PNG or other image file that Pillow can decode (gray or colour; an alpha channel is
    ignored), or a numbered sequence of them, and outputs it with values in 0..1: OUTPUT is
    the colour image (3, rows, cols), RED, GREEN and BLUE its planes and INTENSITY the mean
    of the three (a gray file gives three equal planes). A sequence has ``filecount`` files,
    numbered by a run of ``#`` in ``filename`` (Ikaros 3: ``image_##.jpg`` is image_00.jpg,
    image_01.jpg, ...; ``##`` can number at most 100 files, and more is an error) or by
    ``%d`` (Ikaros 2). The size is ``size_x`` × ``size_y`` when both are set (files of
    another size are resized to it), otherwise the size of the first file. The first image
    is on the outputs from init; on tick k the sequence shows file k modulo ``filecount``,
    and after ``iterations`` passes (0 means forever) the module sends end-of-file, which
    stops the run, and keeps the last image. A file that cannot be read gives a warning and
    the previous image stays."""

    format_name = "image"

    def configure(self):
        capacity = counter_capacity(self.filename)
        if capacity is not None and self.filecount > capacity:
            raise build_error(self, f'filecount {self.filecount} needs more file numbers '
                              f'than "{self.filename}" can write ({capacity})')
        super().configure()
