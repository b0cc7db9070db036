"""NamedWrong: the implementation of fixture_classes/NamedWrong.ikc (test_258)."""
from ikaros.module import Module


class NamedWrong(Module):
    def tick(self):
        self.OUTPUT[0] = 4
