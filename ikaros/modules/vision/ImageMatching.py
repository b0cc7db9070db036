"""ImageMatching: finds the centre of one image in another (a stereo pair's fixation)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, check_image, opencv


def box_sides(left: int, top: int, side: int, rows: int, cols: int) -> np.ndarray:
    """The four sides (top, right, bottom, left) of a square of ``side`` pixels whose
    top-left pixel is (top, left), as rows (x0, y0, x1, y1) in 0..1 of the image."""
    x0, y0, x1, y1 = left / cols, top / rows, (left + side) / cols, (top + side) / rows
    return np.array([[x0, y0, x1, y0], [x1, y0, x1, y1], [x1, y1, x0, y1], [x0, y1, x0, y0]])


class ImageMatching(Module):
    """Looks for the centre of LEFT in RIGHT, as the eyes of a stereo head do when both
    should fixate the same thing. The focus is the square at the centre of LEFT with
    ``focus_size`` of the image's area (its side the square root of focus_size · rows ·
    cols pixels, at least 3); it is compared with every square of that size inside the
    centred square of RIGHT with ``search_size`` of the area, by normalised
    cross-correlation (OpenCV's matchTemplate, TM_CCOEFF_NORMED: 1 for a perfect match).
    OUTPUT is the best match's displacement from the focus (dx, dy) as fractions of the
    image's width and height (positive: right and down); FOCUS and TARGET are the focus
    square in LEFT and the best match in RIGHT as four sides (top, right, bottom, left),
    each a row (x0, y0, x1, y1) in 0..1 for the path widget; PROFILE has one value per
    column of the image: the best correlation of a square centred on that column (0 for
    columns outside the search). LEFT and RIGHT must have the same size; colour images are
    matched on their intensity. The original's class is known only by its interface: this
    is this project's reading of it."""

    focus_size = Parameter(0.01, "the area of the focus square, as a part of the image's",
                           range=(0, 1))
    search_size = Parameter(0.4, "the area of the square searched, as a part of the "
                            "image's", range=(0, 1))

    LEFT = Input("the image whose centre is looked for: gray or colour")
    RIGHT = Input("the image it is looked for in, of the same size")
    OUTPUT = Output("the displacement (dx, dy) of the best match, in 0..1", shape="2")
    FOCUS = Output("the focus square's sides in LEFT, rows (x0, y0, x1, y1)", shape="4, 4")
    TARGET = Output("the best match's sides in RIGHT, rows (x0, y0, x1, y1)", shape="4, 4")
    PROFILE = Output("the best correlation per column", shape="LEFT.size_x")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_image(self.LEFT.shape, "LEFT")
        check_image(self.RIGHT.shape, "RIGHT")
        if self.LEFT.shape[-2:] != self.RIGHT.shape[-2:]:
            raise ValueError(f"LEFT ({self.LEFT.shape}) and RIGHT ({self.RIGHT.shape}) must "
                             f"have the same size")
        self._left, self._right = GrayImage(self.LEFT), GrayImage(self.RIGHT)

    def _squares(self):
        rows, cols = self.LEFT.shape[-2:]
        area = rows * cols
        side = int(min(max(3, round(np.sqrt(self.focus_size * area))), rows, cols))
        search = int(min(max(side, round(np.sqrt(self.search_size * area))), rows, cols))
        search_rows, search_cols = min(search, rows), min(search, cols)
        return (side, (rows - side) // 2, (cols - side) // 2,
                (rows - search_rows) // 2, (cols - search_cols) // 2, search_rows, search_cols)

    def tick(self):
        rows, cols = self.LEFT.shape[-2:]
        side, top, left, s_top, s_left, s_rows, s_cols = self._squares()
        focus = np.ascontiguousarray(self._left()[top:top + side, left:left + side])
        region = np.ascontiguousarray(self._right()[s_top:s_top + s_rows,
                                                    s_left:s_left + s_cols])
        scores = np.nan_to_num(self.cv2.matchTemplate(region, focus,
                                                      self.cv2.TM_CCOEFF_NORMED))
        best_row, best_col = np.unravel_index(np.argmax(scores), scores.shape)
        match_top, match_left = s_top + best_row, s_left + best_col
        self.OUTPUT[...] = ((match_left - left) / cols, (match_top - top) / rows)
        self.FOCUS[...] = box_sides(left, top, side, rows, cols)
        self.TARGET[...] = box_sides(match_left, match_top, side, rows, cols)
        self.PROFILE[...] = 0
        first = s_left + side // 2
        self.PROFILE[first:first + scores.shape[1]] = scores.max(axis=0)
