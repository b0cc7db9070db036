"""BadBoolState: the implementation of fixture_classes/BadBoolState.ikc."""
from ikaros.module import Module


class BadBoolState(Module):
    pass
