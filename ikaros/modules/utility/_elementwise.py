"""A base for modules that combine INPUT1 and INPUT2 element by element."""
from ikaros.module import Module


class ElementWise(Module):
    """Checks in init that the inputs match the output in size, and keeps views of them in
    the output's shape (``self._a``, ``self._b``; ``_b`` is None for an unconnected
    optional INPUT2)."""

    def init(self):
        shape = self.OUTPUT.shape
        for name in ("INPUT1", "INPUT2"):
            x = getattr(self, name)
            if x is not None and x.size != self.OUTPUT.size:
                self.fatal_error(f"INPUT1 and INPUT2 must have the same size; {name} has shape "
                                 f"{x.shape}, the output {shape}")
                return
        self._a = _as_shape(self.INPUT1, shape)
        self._b = None if self.INPUT2 is None else _as_shape(self.INPUT2, shape)


def _as_shape(x, shape):
    return x if x.shape == shape else x.reshape(shape)
