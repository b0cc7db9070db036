"""Base class of the colour modules that take and give the three planes of an image either
as one colour image (INPUT, OUTPUT: (3, rows, cols), docs/images.md) or as three gray
images (INPUT0..2, OUTPUT0..2, as in Ikaros 2)."""
from __future__ import annotations

import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import check_gray, is_colour, opencv


class ThreePlanes(Module):
    """Reads three planes from INPUT or from INPUT0, INPUT1 and INPUT2, and after
    ``compute`` has written OUTPUT, copies its planes to OUTPUT0, OUTPUT1 and OUTPUT2."""

    INPUT = Input("a colour image (3, rows, cols); or connect INPUT0, INPUT1 and INPUT2",
                  optional=True)
    INPUT0 = Input("the first plane (rows, cols), when INPUT is not connected",
                   optional=True)
    INPUT1 = Input("the second plane (rows, cols)", optional=True)
    INPUT2 = Input("the third plane (rows, cols)", optional=True)
    OUTPUT = Output("the result as one image (3, rows, cols)")
    OUTPUT0 = Output("the first plane of OUTPUT")
    OUTPUT1 = Output("the second plane of OUTPUT")
    OUTPUT2 = Output("the third plane of OUTPUT")

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        separate = [self.connected(f"INPUT{i}") for i in range(3)]
        if self.connected("INPUT") == any(separate) or (any(separate) and not all(separate)):
            raise ValueError("connect either INPUT (a colour image) or all three of INPUT0, "
                             "INPUT1 and INPUT2")
        if self.connected("INPUT"):
            shape = self.input_shape("INPUT")
            if shape and not is_colour(shape):
                raise ValueError(f"INPUT must be a colour image (3, rows, cols), not {shape}")
        else:
            shapes = [self.input_shape(f"INPUT{i}") for i in range(3)]
            if not all(shapes):
                return
            for i, s in enumerate(shapes):
                check_gray(s, f"INPUT{i}")
            if len(set(shapes)) > 1:
                raise ValueError(f"INPUT0, INPUT1 and INPUT2 must have the same size, not "
                                 f"{shapes[0]}, {shapes[1]} and {shapes[2]}")
            shape = (3,) + shapes[0]
        if shape:
            self.set_output_shape("OUTPUT", shape)
            for i in range(3):
                self.set_output_shape(f"OUTPUT{i}", shape[1:])

    def init(self):
        self.planes_in = (list(self.INPUT) if self.INPUT is not None
                          else [self.INPUT0, self.INPUT1, self.INPUT2])
        self._copies = list(zip(self.OUTPUT, (self.OUTPUT0, self.OUTPUT1, self.OUTPUT2)))

    def compute(self) -> None:
        """Read ``self.planes_in`` and write ``self.OUTPUT``."""
        raise NotImplementedError

    def tick(self):
        self.compute()
        for plane, out in self._copies:
            np.copyto(out, plane)
