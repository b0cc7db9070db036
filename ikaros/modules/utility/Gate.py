"""Gate: passes its input through or blocks it."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Gate(Module):
    """Copies INPUT to OUTPUT when the gate is open and outputs 0 when it is closed. Without
    INPUT_GATE the parameter ``open`` decides. When INPUT_GATE is connected it decides instead
    of ``open``: a one-element gate opens or closes the whole output (open when its value is
    above 0), and a gate with as many elements as INPUT opens each position separately."""

    open = Parameter(True, "whether the gate is open (used when INPUT_GATE is unconnected)")
    INPUT = Input("the signal to gate")
    INPUT_GATE = Input("gate values: above 0 is open; one element for all, or one per input "
                       "element", optional=True)
    OUTPUT = Output("the input where the gate is open, 0 elsewhere", size_set="INPUT")

    def init(self):
        self._ok = True
        self._gate = None
        if self.INPUT_GATE is not None:
            if self.INPUT_GATE.size == 1:
                self._gate = self.INPUT_GATE.reshape(-1)[:1]
            elif self.INPUT_GATE.size == self.INPUT.size:
                self._gate = self.INPUT_GATE.reshape(self.INPUT.shape)
            else:
                self._ok = False
                self.fatal_error(f"INPUT_GATE has {self.INPUT_GATE.size} elements; it must "
                                 f"have 1 or as many as INPUT ({self.INPUT.size})")

    def tick(self):
        if not self._ok:
            return
        if self._gate is None:
            if self.open:
                self.OUTPUT[...] = self.INPUT
            else:
                self.OUTPUT.fill(0)
        elif self._gate.size == 1 and self.INPUT.size != 1:
            if self._gate[0] > 0:
                self.OUTPUT[...] = self.INPUT
            else:
                self.OUTPUT.fill(0)
        else:
            self.OUTPUT.fill(0)
            np.copyto(self.OUTPUT, self.INPUT, where=self._gate > 0)
