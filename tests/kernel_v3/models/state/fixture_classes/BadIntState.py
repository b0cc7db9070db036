"""BadIntState: the implementation of fixture_classes/BadIntState.ikc."""
from ikaros.module import Module


class BadIntState(Module):
    pass
