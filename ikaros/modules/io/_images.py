"""Helpers shared by the image file modules: conversion between 0..1 float images and 8-bit
files, and base classes for image readers and writers. The convention is in docs/images.md:
values 0..1; gray images (rows, cols); colour images (3, rows, cols), planes R, G, B."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require

from ._files import build_error, has_counter, numbered, resolve


def to_uint8(x: np.ndarray) -> np.ndarray:
    """0..1 floats as 0..255 bytes: clipped, then rounded to the nearest level (NaN is 0)."""
    x = np.nan_to_num(x, nan=0.0, posinf=1.0, neginf=0.0)
    return np.rint(np.clip(x, 0.0, 1.0) * 255.0).astype(np.uint8)


def from_uint8(a: np.ndarray) -> np.ndarray:
    """0..255 bytes as 0..1 floats (value / 255)."""
    return a.astype(np.float32) / np.float32(255.0)


def planes(Image, img, shape=None) -> np.ndarray:
    """A Pillow image as a (3, rows, cols) float32 array in 0..1, resized to ``shape``
    (rows, cols) if given. Gray images give three equal planes; alpha is dropped."""
    mode = img.mode
    if mode in ("I", "F") or mode.startswith("I;16"):
        a = np.asarray(img.convert("F") if mode.startswith("I;16") else img, np.float32)
        gray = a if mode == "F" else a / np.float32(65535.0)
        rgb = np.stack([gray, gray, gray])
    elif mode in ("L", "LA", "1"):
        gray = from_uint8(np.asarray(img.convert("L")))
        rgb = np.stack([gray, gray, gray])
    else:
        rgb = from_uint8(np.asarray(img.convert("RGB"))).transpose(2, 0, 1)
    if shape is not None and rgb.shape[1:] != tuple(shape):
        rows, cols = shape
        rgb = np.stack([np.asarray(Image.fromarray(np.ascontiguousarray(p), "F").resize(
            (cols, rows), Image.BILINEAR), np.float32) for p in rgb])
    return np.clip(rgb, 0.0, 1.0, out=rgb)


def to_pillow(Image, image: np.ndarray):
    """A (rows, cols) gray or (3, rows, cols) colour array in 0..1 as a Pillow image."""
    if image.ndim == 2:
        return Image.fromarray(to_uint8(image), "L")
    return Image.fromarray(np.ascontiguousarray(to_uint8(image).transpose(1, 2, 0)), "RGB")


class ImageFileReader(Module):
    """Base of InputJPEG and InputPNG: reads one image file or a numbered sequence."""

    filename = Parameter("", "the image file; %d (or %02d and so on) is replaced by the "
                         "file number 0, 1, ... to read a sequence; relative to the model "
                         "file's folder")
    filecount = Parameter(1, "number of files in the sequence", type="int")
    iterations = Parameter(0, "how many times the sequence is shown before end-of-file stops "
                           "the run; 0 means forever (the Ikaros 2 default, inf)", type="int")

    OUTPUT = Output("the colour image, (3, rows, cols): planes red, green and blue in 0..1")
    RED = Output("the red plane (rows, cols); the gray level for a gray file")
    GREEN = Output("the green plane (rows, cols); the gray level for a gray file")
    BLUE = Output("the blue plane (rows, cols); the gray level for a gray file")
    INTENSITY = Output("the intensity (rows, cols): the mean of red, green and blue")

    format_name = "image"      # for messages; Pillow detects the actual format from the file

    def requested_shape(self):
        """A requested size (rows, cols), or None for the size of the first file."""
        return None

    def reread_every_tick(self) -> bool:
        return False

    def notify_repeat_enabled(self) -> bool:
        return False

    def configure(self):
        self._Image = require("PIL.Image", "Pillow", extra="image")
        if not self.filename:
            raise build_error(self, f"{type(self).__name__} needs a filename")
        if self.filecount < 1:
            raise build_error(self, "filecount must be at least 1")
        first = self._path(0)
        try:
            image = self._read(first, self.requested_shape())
        except OSError as e:
            raise build_error(self, f'cannot read {self.format_name} file "{first}": '
                              f'{getattr(e, "strerror", None) or e}') from None
        rows, cols = image.shape[1:]
        self.set_output_shape("OUTPUT", (3, rows, cols))
        for name in ("RED", "GREEN", "BLUE", "INTENSITY"):
            self.set_output_shape(name, (rows, cols))
        self._first = image

    def _path(self, index):
        name = numbered(self.filename, index) if has_counter(self.filename) else self.filename
        return resolve(self, name)

    def _read(self, path, shape):
        with self._Image.open(path) as img:
            img.load()
            return planes(self._Image, img, shape)

    def init(self):
        self._shape = self.OUTPUT.shape[1:]
        self._index = None             # the file number now on the outputs
        self._warned = set()
        self._show(0, self._first)
        self._first = None

    def _show(self, index, image):
        self._index = index
        self.OUTPUT[...] = image
        self.RED[...] = image[0]
        self.GREEN[...] = image[1]
        self.BLUE[...] = image[2]
        np.mean(image, axis=0, out=self.INTENSITY)

    def tick(self):
        k = self.clock.tick
        n = self.filecount
        iteration, index = divmod(k, n)
        last = self.iterations > 0 and iteration >= self.iterations - 1 and index == n - 1
        if self.iterations > 0 and iteration >= self.iterations:
            return                          # past the end: keep the last image
        if index == 0 and iteration > 0 and self.notify_repeat_enabled():
            self.print(f"the sequence starts over (iteration {iteration + 1})")
        if index != self._index or self.reread_every_tick():
            path = self._path(index)
            try:
                image = self._read(path, self._shape)
            except (OSError, ValueError) as e:
                if path not in self._warned:
                    self._warned.add(path)
                    self.warning(f'cannot read {self.format_name} file "{path}": '
                                 f'{getattr(e, "strerror", None) or e}; the previous image '
                                 f'is kept')
            else:
                self._show(index, image)
        if last:
            self.end_of_file(f"end of the {self.format_name} sequence")


class ReadOnce(ImageFileReader):
    """An image reader with ``read_once``: with no, the current file is read again on every
    tick (InputJPEG, InputImage)."""

    read_once = Parameter(True, "read each file only when the sequence moves to it; with no, "
                          "the current file is read again on every tick")

    def reread_every_tick(self):
        return not self.read_once


class ImageInputs(Module):
    """Base of the image writers: the image comes from INPUT, INTENSITY or RED/GREEN/BLUE."""

    INPUT = Input("an image to write: (rows, cols) gray or (3, rows, cols) colour, in 0..1",
                  optional=True)
    INTENSITY = Input("a gray image to write, (rows, cols), in 0..1 (used when INPUT is not "
                      "connected)", optional=True)
    RED = Input("the red plane of a colour image to write (used when INPUT and INTENSITY are "
                "not connected; an unconnected plane is 0)", optional=True)
    GREEN = Input("the green plane of a colour image to write", optional=True)
    BLUE = Input("the blue plane of a colour image to write", optional=True)

    def image_source(self):
        """A function that gives the image to write, (rows, cols) or (3, rows, cols), checked
        against the connected inputs; call it in init."""
        kinds = [n for n, connected in (("INPUT", self.INPUT is not None),
                                        ("INTENSITY", self.INTENSITY is not None),
                                        ("RED/GREEN/BLUE", any(x is not None for x in (
                                            self.RED, self.GREEN, self.BLUE))))
                 if connected]
        if not kinds:
            raise ValueError("connect INPUT, INTENSITY, or RED, GREEN and BLUE")
        if len(kinds) > 1:
            self.warning(f"{' and '.join(kinds)} are connected; only {kinds[0]} is written")
        if self.INPUT is not None:
            x = self.INPUT
            if x.ndim == 2 or (x.ndim == 3 and x.shape[0] == 3):
                return lambda: self.INPUT
            if x.ndim == 1:
                return lambda: self.INPUT.reshape(1, -1)
            raise ValueError(f"INPUT has shape {x.shape}; an image is (rows, cols) or "
                             f"(3, rows, cols)")
        if self.INTENSITY is not None:
            shape = self.INTENSITY.shape if self.INTENSITY.ndim == 2 else (1, -1)
            return lambda: self.INTENSITY.reshape(shape)
        chans = [self.RED, self.GREEN, self.BLUE]
        shapes = {c.shape for c in chans if c is not None}
        if len(shapes) > 1:
            raise ValueError(f"RED, GREEN and BLUE have different shapes {sorted(shapes)}")
        shape = shapes.pop()
        shape = shape if len(shape) == 2 else (1, int(np.prod(shape)))
        rgb = np.zeros((3,) + shape, dtype=np.float32)

        def colour():
            for i, c in enumerate(chans):
                if c is not None:
                    rgb[i] = c.reshape(shape)
            return rgb
        return colour

    def check_range(self, image):
        """Warn once when values fall outside 0..1 (they are clipped when converted)."""
        if not getattr(self, "_warned_range", False) and \
                (image.min() < 0.0 or image.max() > 1.0):
            self._warned_range = True
            self.warning("some values are outside 0..1 and are clipped (this warning is "
                         "given once)")


class ImageFileWriter(ImageInputs):
    """Base of OutputJPEG and OutputPNG: writes one image file per tick."""

    filename = Parameter("", "the file to write; %d (or %02d and so on) is replaced by the "
                         "file number, which is offset + the number of ticks so far; "
                         "without %d every image overwrites the same file; relative to the "
                         "model file's folder or the user-data folder (ikaros -u)")
    scale = Parameter(1.0, "factor the image is multiplied by before it is written; values "
                      "outside 0..1 are then clipped")
    suppress = Parameter(0, "number of initial ticks on which nothing is written (their file "
                         "numbers are skipped)", type="int")
    offset = Parameter(0, "value added to the file number", type="int")
    single_trig = Parameter(False, "with WRITE connected, write only when WRITE rises from 0 "
                            "or below to above 0, not on every tick it is above 0")
    increase_file_no_on_trig = Parameter(False, "advance the file number only when a file is "
                                         "written, rather than on every tick")
    WRITE = Input("when connected, an image is written only on ticks when its first element "
                  "is above 0", optional=True)

    format_name = "image"
    pillow_format = "PNG"

    def save_options(self) -> dict:
        return {}

    def configure(self):
        self._Image = require("PIL.Image", "Pillow", extra="image")
        if not self.filename:
            raise build_error(self, f"{type(self).__name__} needs a filename")

    def init(self):
        self._image = self.image_source()
        self._counter = 0
        self._ticks = 0
        self._last_write = False
        self._failing = False

    def single_trigger_on(self) -> bool:
        """Whether WRITE writes only on its rises."""
        return self.single_trig

    def file_name(self, counter: int) -> str:
        """The name of the file written with this counter (files written or ticks so far)."""
        return numbered(self.filename, self.offset + counter)

    def tick(self):
        write = True
        if self.WRITE is not None:
            on = bool(self.WRITE.flat[0] > 0)
            write = on and not (self.single_trigger_on() and self._last_write)
            self._last_write = on
        if self._ticks < self.suppress:
            write = False
        self._ticks += 1
        if write:
            self._write(self.file_name(self._counter))
        if write or not self.increase_file_no_on_trig:
            self._counter += 1

    def _write(self, name):
        image = self._image()
        if self.scale != 1.0:
            image = image * np.float32(self.scale)
        self.check_range(image)
        path = name
        try:
            path = resolve(self, name, write=True)
            to_pillow(self._Image, image).save(path, format=self.pillow_format,
                                               **self.save_options())
        except (OSError, ValueError) as e:
            if not self._failing:
                self.warning(f'cannot write {self.format_name} file "{path}": '
                             f'{getattr(e, "strerror", None) or e}')
            self._failing = True
        else:
            self._failing = False
