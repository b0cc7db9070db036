"""DepthContourTrace: the outline of a foreground region as line segments."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import opencv


class DepthContourTrace(Module):
    """Traces the outline of the largest foreground region of INPUT (pixels above 0.5, such
    as DepthSegmentation's output) with OpenCV's findContours, smooths it with a running mean
    over 2 · segment_smoothing + 1 outline points, and cuts it into segments of about
    segment_length pixels: OUTPUT has one row (x0, y0, x1, y1) per segment, in pixels
    (x = column, y = row), at most segment_count of them, and LENGTH says how many. BOX is
    the region's bounding box as its four corners (x, y) in pixels, clockwise from the
    top-left.
    DEBUG is half the input with the segments drawn at 1; it has the input's size (Ikaros 2
    fixed it at 640 × 480). (The reference describes Ikaros 2's tracing in a sentence and no
    golden output reaches the class: the tracing, smoothing and cutting are this project's
    reading.)"""

    segment_length = Parameter(15.0, "length of a segment, in pixels")
    segment_count = Parameter(250, "the largest number of segments", type="int")
    segment_smoothing = Parameter(1, "outline points on each side in the running mean",
                                  type="int")
    INPUT = Input("the foreground image (rows, cols): 1 inside the region")
    OUTPUT = Output("one row (x0, y0, x1, y1) per segment, in pixels",
                    shape="@segment_count, 4")
    BOX = Output("the bounding box's corners (x, y), clockwise from the top-left",
                 shape="4, 2")
    LENGTH = Output("the number of segments", size="1")
    DEBUG = Output("the input at half strength with the segments drawn", size_set="INPUT")

    def configure(self):
        self.cv2 = opencv()
        if self.segment_length <= 0 or self.segment_count < 1:
            raise ValueError("segment_length must be above 0 and segment_count at least 1")

    def init(self):
        if self.INPUT.ndim != 2:
            raise ValueError(f"INPUT must be an image (rows, cols), not shape "
                             f"{self.INPUT.shape}")
        self._mask = np.zeros(self.INPUT.shape, np.uint8)

    def tick(self):
        cv2 = self.cv2
        np.greater(self.INPUT, 0.5, out=self._mask, casting="unsafe")
        contours, _ = cv2.findContours(self._mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        self.OUTPUT.fill(0)
        self.BOX.fill(0)
        np.multiply(self.INPUT, 0.5, out=self.DEBUG)
        self.LENGTH[0] = 0
        if not contours:
            return
        outline = max(contours, key=cv2.contourArea).reshape(-1, 2).astype(np.float64)
        x, y, w, h = cv2.boundingRect(outline.astype(np.int32))
        self.BOX[...] = [[x, y], [x + w - 1, y], [x + w - 1, y + h - 1], [x, y + h - 1]]
        k = self.segment_smoothing
        if k > 0 and len(outline) > 2 * k:
            kernel = np.ones(2 * k + 1) / (2 * k + 1)
            wrapped = np.concatenate([outline[-k:], outline, outline[:k]])
            outline = np.stack([np.convolve(wrapped[:, i], kernel, "valid") for i in (0, 1)],
                               axis=1)
        closed = np.vstack([outline, outline[:1]])
        steps = np.hypot(*np.diff(closed, axis=0).T)
        along = np.concatenate([[0], np.cumsum(steps)])
        count = int(min(self.segment_count, max(1, np.floor(along[-1] / self.segment_length))))
        if along[-1] <= 0:
            return
        marks = np.linspace(0, along[-1], count + 1)
        points = np.stack([np.interp(marks, along, closed[:, i]) for i in (0, 1)], axis=1)
        self.OUTPUT[:count] = np.hstack([points[:-1], points[1:]])
        self.LENGTH[0] = count
        for x0, y0, x1, y1 in self.OUTPUT[:count]:
            cv2.line(self.DEBUG, (int(round(x0)), int(round(y0))),
                     (int(round(x1)), int(round(y1))), 1.0, 1)
