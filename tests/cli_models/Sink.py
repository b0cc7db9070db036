from ikaros.module import Input, Module


class Sink(Module):
    """Takes an input and does nothing (for tests)."""
    INPUT = Input("anything")
