"""ImageConvolution: the image filtered with a kernel given as a parameter."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, interior, opencv, planes, with_size


class ImageConvolution(Module):
    """Filters the image with ``kernel``, multiplies by ``scale``, adds ``bias`` and with
    ``rectify`` takes the absolute value, as Ikaros 2 does: OUTPUT[r, c] =
    scale · Σ kernel[i, j] · INPUT[r + i, c + j] + bias, summed over the kernel's rows i and
    columns j. The kernel is applied as written, not flipped (a correlation, what the
    golden outputs of Ikaros 2 show: kernel="1 0 -1; ..." gives a negative output where the
    image gets brighter to the right). The output is the part of the image where the whole
    kernel fits (kernel rows - 1 and columns - 1 smaller); a colour image is filtered plane
    by plane and a vector is a one-row image. Without a ``kernel`` (the default; Ikaros 2
    gives it no default either) the kernel is empty, as in the original: the output is one
    row and one column larger than the image and holds ``bias`` (0), with a warning. The
    kernel's values, scale and bias may change while the model runs, its size may not."""

    scale = Parameter(1.0, "multiplies the filtered image")
    bias = Parameter(0.0, "added after scaling")
    rectify = Parameter(False, "take the absolute value of the result")
    kernel = Parameter("", "the kernel, a matrix (rows separated by ;); empty: no kernel",
                       type="matrix")
    INPUT = Input("the image: gray (rows, cols), colour (3, rows, cols) or a vector (one "
                  "row)")
    OUTPUT = Output("the filtered image, kernel rows - 1 and columns - 1 smaller than INPUT")

    def configure(self):
        self.cv2 = opencv()

    def _kernel(self) -> np.ndarray:
        kernel = np.asarray(self.kernel, np.float32)
        return kernel.reshape(0, 0) if kernel.size == 0 else np.atleast_2d(kernel)

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            shape = image_shape(shape)
            rows, cols = self._kernel().shape
            out_rows, out_cols = shape[-2] - rows + 1, shape[-1] - cols + 1
            if out_rows < 1 or out_cols < 1:
                raise ValueError(f"the image ({shape[-2]} x {shape[-1]}) is smaller than the "
                                 f"kernel ({rows} x {cols})")
            self.set_output_shape("OUTPUT", with_size(shape, out_rows, out_cols))

    def init(self):
        self._shape = self._kernel().shape
        image = as_image(self.INPUT)
        self._full = np.zeros(image.shape[-2:], np.float32)
        self._valid = None
        if self._shape[0]:
            self._valid = interior(self._full, 0, 0, *self.OUTPUT.shape[-2:])
        else:
            self.warning("no kernel is set: the kernel is empty and OUTPUT holds bias, "
                      "as in the original")
        self._pairs = list(zip(planes(image), planes(self.OUTPUT)))
        self._key = None

    def tick(self):
        if self._valid is None:
            self.OUTPUT.fill(abs(self.bias) if self.rectify else self.bias)
            return
        key = (np.asarray(self.kernel).tobytes(), self.scale)
        if key != self._key:
            self._key = key
            self._make_kernel()
        for src, dst in self._pairs:
            # the kernel's top-left entry at each output pixel: anchor (0, 0)
            self.cv2.filter2D(src, -1, self._scaled, dst=self._full, anchor=(0, 0),
                              delta=self.bias, borderType=self.cv2.BORDER_REFLECT)
            if self.rectify:
                np.abs(self._valid, out=dst)
            else:
                np.copyto(dst, self._valid)

    def _make_kernel(self):
        kernel = self._kernel()
        if kernel.shape != self._shape:
            self.warning(f"the kernel's size cannot change while the model runs "
                         f"({self._shape[0]} x {self._shape[1]}); the new kernel "
                         f"{kernel.shape[0]} x {kernel.shape[1]} is not used")
            return
        self._scaled = np.ascontiguousarray(kernel * np.float32(self.scale))
