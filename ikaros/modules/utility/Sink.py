"""Sink: accepts an input and does nothing with it."""
from ikaros.module import Input, Module


class Sink(Module):
    """Accepts any input and does nothing with it. Use it to give an otherwise unused output
    somewhere to go, for example to keep a module's output in a view."""

    INPUT = Input("anything; it is ignored")
