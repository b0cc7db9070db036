"""Concat: copies an input that gathers several connections."""
from ikaros.module import Input, Module, Output, Parameter


class Concat(Module):
    """Copies its input to its output. Connect several sources to INPUT: the kernel lays
    them end to end, in an Ikaros 2 file with the connection declared last first, as
    Ikaros 2 does (``concatenation="declared"`` keeps the declaration order; see the
    language reference), so the output is their concatenation. A single connection is
    copied with its shape."""

    debug = Parameter(False, "print the output on every tick")
    INPUT = Input("the values to concatenate; any number of connections")
    OUTPUT = Output("the concatenated input", size_set="INPUT")

    def tick(self):
        self.OUTPUT[...] = self.INPUT
        if self.debug:
            self.print(" ".join(f"{v:g}" for v in self.OUTPUT.flat))
