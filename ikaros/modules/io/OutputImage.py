"""OutputImage: the Ikaros 3 image writer (JPEG or PNG, by the file's extension)."""
import os

from ikaros.module import Parameter

from ._files import build_error, numbered
from ._images import ImageFileWriter

_FORMATS = {".jpg": "JPEG", ".jpeg": "JPEG", ".png": "PNG"}


class OutputImage(ImageFileWriter):
    """Ikaros 3's name for the image writers (Ikaros 2: OutputJPEG, OutputPNG). Writes an
    image on every tick to a JPEG or PNG file, as ``format`` says (``auto``, the default:
    by the extension of ``filename``, .jpg, .jpeg or .png). The image is INPUT ((rows,
    cols) gray or (3, rows, cols) colour) if it is connected, else INTENSITY (gray), else
    RED, GREEN and BLUE (colour; an unconnected plane is 0). Values are multiplied by
    ``scale``, clipped to 0..1 (with a warning once) and stored as 8-bit levels
    round(255·v); JPEG files are saved with ``quality``. The file name may hold a run of
    ``#`` (Ikaros 3: ``##`` is two digits, zero-padded) or ``%d`` (Ikaros 2), replaced by
    the file number: ``start_index`` (Ikaros 3) plus ``offset`` plus the number of ticks so
    far, or plus the number of files written with ``increase_file_no_on_trig``; without it
    every tick overwrites the same file. A relative name is in ``directory`` (Ikaros 3;
    created when missing) if it is set, which is itself relative to the model file's folder
    or the user-data folder (ikaros -u). Nothing is written on the first ``suppress`` ticks,
    nor, when WRITE is connected, on ticks when its first element is not above 0 (with
    ``single_trig``, or its Ikaros 3 name ``single_trigger``, only on ticks when it rises
    above 0). A file that cannot be written gives a warning and the run goes on, and the
    next write tries again. In a file of dialect 3 the defaults are Ikaros 3's: filename
    output.jpg and quality 90."""

    filename = Parameter("", "the file to write; %d or ## is replaced by the file number; "
                         "relative to directory, or to the model file's folder or the "
                         "user-data folder (ikaros -u)", default_v3="output.jpg")
    format = Parameter("auto", "the file format (auto: by the file's extension)",
                       options="auto/jpeg/png")
    quality = Parameter(100, "JPEG quality, 1 (smallest file) to 100 (best image)",
                        type="int", default_v3=90)
    directory = Parameter("", "the folder of the files (created when missing); empty: the "
                          "model file's folder or the user-data folder")
    start_index = Parameter(0, "the number of the first file (added to offset)", type="int",
                            range=(0, None))
    single_trigger = Parameter(False, "Ikaros 3's name of single_trig")

    def configure(self):
        super().configure()
        if self.format == "auto":
            ext = os.path.splitext(self.filename)[1].lower()
            if ext not in _FORMATS:
                raise build_error(self, f'cannot tell the image format of "{self.filename}": '
                                  f'use .jpg, .jpeg or .png, or set format')
            self.pillow_format = _FORMATS[ext]
        else:
            self.pillow_format = self.format.upper()
        self.format_name = self.pillow_format

    def single_trigger_on(self):
        return self.single_trig or self.single_trigger

    def file_name(self, counter):
        name = numbered(self.filename, self.start_index + self.offset + counter)
        return os.path.join(self.directory, name) if self.directory else name

    def save_options(self):
        if self.pillow_format == "JPEG":
            return {"quality": max(1, min(100, self.quality))}
        return {}
