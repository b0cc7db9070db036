"""AttentionWindow: an object window cut out of the image and resampled."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, opencv, planes, with_size


class AttentionWindow(Module):
    """Cuts a window out of the image and resamples it (bilinear, OpenCV's warpAffine) to
    ``output_size_x`` x ``output_size_y``; parts outside the image are 0. The window is
    chosen from the first of these that gives one: TOP_DOWN_BOUNDS, TOP_DOWN_POSITION, the
    first row of BOTTOM_UP_BOUNDS, the first row of BOTTOM_UP_POSITION (the bottom-up ones
    only when BOTTOM_UP_COUNT, if connected, is at least 1). Positions are (x, y) and
    bounds (x0, y0, x1, y1), or the four corners (x, y) of a box as in the face detectors'
    FACE_BOUNDS, all as fractions of the image's width and height. Around a position the
    window is ``window_size_x`` x ``window_size_y`` pixels when both are set, otherwise a
    square of 2·window_radius + 1 pixels. Bounds with no area are ignored. When nothing
    gives a window, OUTPUT is 0. A vector is a one-row image. (The reference gives Ikaros
    2's interface and purpose; the window rules here are this project's reading. Ikaros 2's
    one golden case, every input a changing 4-element vector, shows only tick 0: there,
    with all inputs still 0, OUTPUT is 0 as here; then the original stopped before its
    output file was written out (the file ends inside that record, after 61 of OUTPUT's
    64 rows), so what it computes once the inputs change, and why it stopped, is not
    known.)"""

    window_radius = Parameter(15, "half the side of the square window around a position, "
                              "in pixels")
    window_size_x = Parameter(0, "width of the window around a position, in pixels "
                              "(0: use window_radius)")
    window_size_y = Parameter(0, "height of the window around a position, in pixels "
                              "(0: use window_radius)")
    output_size_x = Parameter(64, "width of the output")
    output_size_y = Parameter(64, "height of the output")
    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    BOTTOM_UP_POSITION = Input("detected positions, one row each: x, y", optional=True)
    BOTTOM_UP_BOUNDS = Input("detected bounds, one row each: x0, y0, x1, y1 or four corners",
                             optional=True)
    BOTTOM_UP_COUNT = Input("how many bottom-up rows are valid", optional=True)
    TOP_DOWN_POSITION = Input("a position to look at: x, y", optional=True)
    TOP_DOWN_BOUNDS = Input("a box to look at: x0, y0, x1, y1 or four corners", optional=True)
    OUTPUT = Output("the window, output_size_y x output_size_x, gray or colour as INPUT")

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if self.output_size_x < 1 or self.output_size_y < 1:
            raise ValueError("output_size_x and output_size_y must be at least 1")
        if shape:
            shape = image_shape(shape)
            self.set_output_shape("OUTPUT", with_size(shape, self.output_size_y,
                                                      self.output_size_x))

    def init(self):
        self._image = as_image(self.INPUT)
        self._pairs = list(zip(planes(self._image), planes(self.OUTPUT)))
        self._size = (self.output_size_x, self.output_size_y)

    def tick(self):
        window = self.window()
        if window is None:
            self.OUTPUT.fill(0.0)
            return
        x0, y0, x1, y1 = window
        ox, oy = self._size
        sx, sy = (x1 - x0) / ox, (y1 - y0) / oy
        # output pixel centre j + 0.5 comes from x0 + (j + 0.5) sx; OpenCV's pixel centres
        # are at integer coordinates
        matrix = np.array([[sx, 0.0, x0 + 0.5 * sx - 0.5], [0.0, sy, y0 + 0.5 * sy - 0.5]])
        cv2 = self.cv2
        for src, dst in self._pairs:
            cv2.warpAffine(src, matrix, self._size, dst=dst,
                           flags=cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP,
                           borderMode=cv2.BORDER_CONSTANT, borderValue=0.0)

    def window(self):
        """The window (x0, y0, x1, y1) in pixels, or None."""
        rows, cols = self._image.shape[-2:]
        bottom_up = self.BOTTOM_UP_COUNT is None or self.BOTTOM_UP_COUNT.flat[0] >= 1
        for values, is_box, active in ((self.TOP_DOWN_BOUNDS, True, True),
                                       (self.TOP_DOWN_POSITION, False, True),
                                       (self.BOTTOM_UP_BOUNDS, True, bottom_up),
                                       (self.BOTTOM_UP_POSITION, False, bottom_up)):
            if values is None or not active or values.size < 2:
                continue
            row = (values[0] if values.ndim == 2 else values.ravel()).astype(np.float64)
            if is_box:
                if row.size < 4:
                    continue
                xs, ys = row[0::2] * cols, row[1::2] * rows
                box = (xs.min(), ys.min(), xs.max(), ys.max())
                if box[2] > box[0] and box[3] > box[1]:
                    return box
            else:
                x, y = row[0] * cols, row[1] * rows
                if self.window_size_x > 0 and self.window_size_y > 0:
                    w, h = self.window_size_x, self.window_size_y
                else:
                    w = h = 2 * self.window_radius + 1
                return x - w / 2, y - h / 2, x + w / 2, y + h / 2
        return None
