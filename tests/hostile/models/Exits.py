"""A module that calls sys.exit() or raises KeyboardInterrupt."""
import sys

from ikaros.module import Module, Output, Parameter


class Exits(Module):
    """Leaves in init or tick."""
    where = Parameter("tick", "init, tick or interrupt", type="string")
    OUTPUT = Output("nothing", size_x="1")

    def init(self):
        if self.where == "init":
            sys.exit(3)

    def tick(self):
        if self.where == "tick":
            sys.exit()
        if self.where == "interrupt":
            raise KeyboardInterrupt
