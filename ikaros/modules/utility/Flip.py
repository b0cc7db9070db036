"""Flip: mirrors or turns a matrix."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

_TURNS = {"rotate-left": 1, "rotate-right": -1, "rotate-180": 2}


class Flip(Module):
    """Mirrors INPUT up-down or left-right, or turns it a quarter turn left (counterclockwise,
    as seen with row 0 at the top), a quarter turn right, or half a turn; ``none`` copies it.
    It works on the last two axes, so a colour image (3, rows, cols) is flipped channel by
    channel; a 1-D input is one row. A quarter turn swaps the number of rows and columns:
    the output is cols x rows (Ikaros 2 kept the input's size, which garbled a non-square
    matrix)."""

    type = Parameter("up-down", "what to do",
                     options="none/up-down/left-right/rotate-left/rotate-right/rotate-180")
    INPUT = Input("the matrix")
    OUTPUT = Output("the flipped or turned matrix")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        self.set_output_shape("OUTPUT", self._shape(self.type, tuple(shape)))

    def init(self):
        self._built_type = self.type   # the output's shape follows the type at build time
        self._warned = False

    def _shape(self, kind, shape):
        if kind not in ("rotate-left", "rotate-right"):
            return shape
        return (shape[0], 1) if len(shape) == 1 else shape[:-2] + (shape[-1], shape[-2])

    def tick(self):
        kind = self.type
        x = self.INPUT
        if self._shape(kind, x.shape) != self.OUTPUT.shape:
            if not self._warned:
                self._warned = True
                self.warning(f'type "{kind}" does not fit the output shape set for '
                             f'"{self._built_type}"; using "{self._built_type}"')
            kind = self._built_type
        if kind in _TURNS:
            m = x.reshape(1, -1) if x.ndim == 1 else x
            self.OUTPUT[...] = np.rot90(m, _TURNS[kind], axes=(-2, -1)).reshape(
                self.OUTPUT.shape)
        elif kind == "up-down" and x.ndim > 1:
            self.OUTPUT[...] = x[..., ::-1, :]
        elif kind == "left-right":
            self.OUTPUT[...] = x[..., ::-1]
        else:
            self.OUTPUT[...] = x.reshape(self.OUTPUT.shape)
