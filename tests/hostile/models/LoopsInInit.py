"""A module whose init never returns; with swallow="yes" it also swallows Ctrl-C."""
import os

from ikaros.module import Module, Output, Parameter


class LoopsInInit(Module):
    """Loops in init (after writing the file ``marker``, if given)."""
    marker = Parameter("", "a file written when init starts", type="string")
    swallow = Parameter(False, "catch KeyboardInterrupt and go on looping")
    OUTPUT = Output("nothing", size_x="1")

    def init(self):
        if self.marker:
            with open(self.marker, "w") as f:
                f.write(str(os.getpid()))
        while True:
            try:
                while True:
                    pass
            except KeyboardInterrupt:
                if not self.swallow:
                    raise
