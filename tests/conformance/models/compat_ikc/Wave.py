"""Code for the Wave class declared in Wave.ikc."""
from ikaros.module import Module


class Wave(Module):
    def tick(self):
        self.OUTPUT[:] = (self.type, self.tick_, self.init_, len(self.stop_))
