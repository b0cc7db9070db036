"""TwiceBoundState: the implementation of fixture_classes/TwiceBoundState.ikc."""
from ikaros.module import Module


class TwiceBoundState(Module):
    pass
