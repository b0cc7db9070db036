"""Code for the IkcSizes class, whose parameters and ports are declared in IkcSizes.ikc:
A holds n, B the input's sum, C the input's first element."""
from ikaros.module import Module


class IkcSizes(Module):
    def tick(self):
        self.A[...] = self.n
        self.B[...] = self.INPUT.sum()
        self.C[...] = self.INPUT.flat[0]
