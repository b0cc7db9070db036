"""TouchBoardGraph: a bar graph image of Touch Board values."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class TouchBoardGraph(Module):
    """Draws INPUT (TouchBoard's OUTPUT, or any values) as a bar graph image for the web
    UI's image widget: one bar per element, ``bar_width`` pixels wide with one pixel
    between bars, as high as the value's share of ``max`` (clipped to 0..max) of ``height``
    pixels, bars 1 on a 0 ground. The Ikaros 2 class drew in its own window and had no
    output; here the graph is the output GRAPH."""

    max = Parameter(1024.0, "the value of a bar of full height")
    height = Parameter(64, "the height of the image in pixels", type="int")
    bar_width = Parameter(8, "the width of each bar in pixels", type="int")
    INPUT = Input("the values to draw", flatten=True)
    GRAPH = Output("the bar graph: rows from top to bottom, 1 inside the bars")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is not None:
            n = int(np.prod(shape)) if shape else 0
            self.set_output_shape("GRAPH", (self.height, max(1, n * (self.bar_width + 1) - 1)))

    def init(self):
        if self.height < 1 or self.bar_width < 1 or self.max <= 0:
            raise ValueError("height and bar_width must be 1 or more and max above 0")
        self._rows = np.arange(self.height, 0, -1).reshape(-1, 1)    # height of each row

    def tick(self):
        self.GRAPH.fill(0)
        levels = np.clip(self.INPUT.reshape(-1) / self.max, 0, 1) * self.height
        w = self.bar_width
        for k, level in enumerate(np.round(levels)):
            self.GRAPH[:, k * (w + 1):k * (w + 1) + w] = self._rows <= level
