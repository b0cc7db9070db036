"""MatrixTranslation: shifts the content of a matrix."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._resample import round_half_away


class MatrixTranslation(Module):
    """Shifts the content of INPUT (an image, say) by X (first element) columns to the right
    and Y (first element) rows down: OUTPUT[i, j] = INPUT[i - Y, j - X], with X and Y rounded
    to the nearest whole number (halves away from zero), so every element moves by the same
    amount. Elements that come from
    outside the input are 0; nothing wraps around. Works on the last two axes, so a colour
    image (3, rows, cols) shifts as a whole; a 1-D input is one row."""

    debug = Parameter(False, "print the shift on every tick")
    INPUT = Input("the matrix to shift")
    X = Input("the shift to the right, in columns; its first element is used")
    Y = Input("the shift down, in rows; its first element is used")
    OUTPUT = Output("the shifted matrix", size_set="INPUT")

    def tick(self):
        tx, ty = float(self.X.flat[0]), float(self.Y.flat[0])
        if self.debug:
            self.print(f"shift {tx:g}, {ty:g}")
        x = self.INPUT if self.INPUT.ndim > 1 else self.INPUT.reshape(1, -1)
        out = self.OUTPUT if self.OUTPUT.ndim > 1 else self.OUTPUT.reshape(1, -1)
        out.fill(0)
        if not (np.isfinite(tx) and np.isfinite(ty)):
            return
        rows, cols = x.shape[-2], x.shape[-1]
        # output element (i, j) reads source (i - dy, j - dx)
        dx, dy = int(round_half_away(tx)), int(round_half_away(ty))
        if abs(dx) >= cols or abs(dy) >= rows:
            return
        out[..., max(dy, 0):rows + min(dy, 0), max(dx, 0):cols + min(dx, 0)] = \
            x[..., max(-dy, 0):rows - max(dy, 0), max(-dx, 0):cols - max(dx, 0)]
