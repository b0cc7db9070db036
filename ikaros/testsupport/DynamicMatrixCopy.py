"""DynamicMatrixCopy: a dynamic output whose capacity is its input's shape."""
import numpy as np

from ikaros.module import Input, Output

from ikaros.testsupport._internal import InternalModule, shape_text


class DynamicMatrixCopy(InternalModule):
    """OUTPUT is a dynamic output of capacity ``INPUT.shape`` (known only once INPUT's
    source is sized). In init it prints ``DYNAMIC INPUT CAPACITY RESOLVED capacity=RxC``;
    every tick OUTPUT takes INPUT's shape and values."""

    INPUT = Input("any matrix", optional=True)
    OUTPUT = Output("a copy of INPUT", dynamic=True, capacity="INPUT.shape")

    def init(self):
        self.print(f"DYNAMIC INPUT CAPACITY RESOLVED "
                   f"capacity={shape_text(self.OUTPUT.capacity)}")

    def tick(self):
        self.OUTPUT.set(np.asarray(self.INPUT))
