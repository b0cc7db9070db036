"""ImageConvolution: convolution with a kernel given as a parameter."""
import numpy as np

from ikaros.module import Parameter

from ._filters import KernelFilter


class ImageConvolution(KernelFilter):
    """Convolves the image with ``kernel`` (a matrix, in the mathematical sense: the kernel
    is flipped, as scipy.signal.convolve2d does), multiplies by ``scale``, adds ``bias`` and
    with ``rectify`` takes the absolute value, as Ikaros 2 does. As in Ikaros 2 the output
    is the part of the image where the whole kernel fits (kernel rows - 1 and columns - 1
    smaller); a colour image is filtered plane by plane. The kernel's values, scale and
    bias may change while the model runs, its size may not. (The Ikaros 2 class gives
    ``kernel`` no default; "1", which copies the image, is this module's. Whether it flips
    the kernel is not in the reference: this module convolves, as the class's name says.)"""

    scale = Parameter(1.0, "multiplies the convolution")
    bias = Parameter(0.0, "added after scaling")
    rectify = Parameter(False, "take the absolute value of the result")
    kernel = Parameter("1", "the convolution kernel, a matrix (rows separated by ;)",
                       type="matrix")

    def kernel_shape(self):
        return tuple(np.atleast_2d(self.kernel).shape)

    def kernel_key(self):
        return np.asarray(self.kernel).tobytes(), self.scale

    def make_kernel(self):
        kernel = np.atleast_2d(self.kernel)
        if kernel.shape != (self.kernel_rows, self.kernel_cols):
            self.warning(f"the kernel's size cannot change while the model runs "
                         f"({self.kernel_rows} x {self.kernel_cols}); the new kernel "
                         f"{kernel.shape[0]} x {kernel.shape[1]} is not used")
            return
        self._flipped = np.ascontiguousarray(kernel[::-1, ::-1] * self.scale, np.float32)

    def filter(self, src, dst):
        self.cv2.filter2D(src, -1, self._flipped, dst=dst, delta=self.bias,
                          borderType=self.cv2.BORDER_REFLECT)
        if self.rectify:
            np.abs(dst, out=dst)
