"""Print: prints its input."""
import numpy as np

from ikaros.module import Input, Module, Parameter


class Print(Module):
    """Prints the values of its input through the kernel's log (which shows them as
    ``NAME: values``) on every tick that is a multiple of ``interval``. Each value is
    formatted with ``format`` (printf style); the values of a row are separated by spaces and
    rows by ``;``; higher ranks are printed as their flattened rows.

    INPUT is optional, as in Ikaros 3 (Print is not in the reference's Ikaros 2 catalogue):
    a Print whose INPUT is not connected prints nothing. INPUT uses labels (Ikaros 3
    ``use_label``): when exactly one of its connections has a ``label``, the values are
    printed after it, as ``signal = 7``."""

    format = Parameter("%.4g", "printf-style format of each value")
    interval = Parameter(1, "ticks between printouts", type="int")
    INPUT = Input("the values to print (optional: unconnected, nothing is printed)",
                  optional=True, use_label=True)

    def init(self):
        label = self.input_label("INPUT")
        self._prefix = f"{label} = " if label is not None else ""

    def tick(self):
        if self.INPUT is None or self.clock.tick % max(1, self.interval) != 0:
            return
        data = self.INPUT
        rows = data.reshape(-1, data.shape[-1]) if data.ndim >= 2 else data.reshape(1, -1)
        try:
            text = np.char.mod(self.format, rows)
        except (TypeError, ValueError):
            text = np.char.mod("%.4g", rows)
        self.print(self._prefix + "; ".join(" ".join(row) for row in text.tolist()))
