"""PersistentStateTestModule: state of every kind, printed every tick."""
from ikaros.module import Input, Output, Parameter, State

from ikaros.testsupport._internal import InternalModule, text


class PersistentStateTestModule(InternalModule):
    """Holds state of every kind for the state tests. STATE, a persistent output shaped
    like ``data``, is set to ``data`` at init; MEMORY, private matrix state shaped like
    ``memory``, to ``memory``. The scalar state items bias (float), gain (double), count
    (int), active (bool) and label (string) start at 0, 1, 0, true and "untrained"; with
    ``train`` init sets them to 0.25, 1.5, 42, false and "trained". Ticks change nothing;
    every tick prints ``STATE: ...``, ``MEMORY: ...`` and ``SCALAR_STATE: bias gain count
    active label`` (active as 1 or 0), so a state loaded after init is what it prints."""

    data = Parameter([1, 2, 3], "STATE after init", type="array")
    memory = Parameter([0, 0, 0], "MEMORY after init", type="array")
    train = Parameter(False, "set the scalar state to 0.25, 1.5, 42, false, trained at init")
    INPUT = Input("not read", optional=True)
    STATE = Output("data, as set at init or loaded", shape="data.shape", persistent=True)
    MEMORY = State(description="memory, as set at init or loaded", shape="memory.shape")
    bias = State(0.0, "a float", type="float")
    gain = State(1.0, "a double", type="double")
    count = State(0, "an int")
    active = State(True, "a bool")
    label = State("untrained", "a string")

    def init(self):
        self.STATE[...] = self.data
        self.MEMORY[...] = self.memory
        if self.train:
            self.bias, self.gain, self.count, self.active, self.label = \
                0.25, 1.5, 42, False, "trained"

    def tick(self):
        self.print("STATE: " + " ".join(text(float(v)) for v in self.STATE.flat))
        self.print("MEMORY: " + " ".join(text(float(v)) for v in self.MEMORY.flat))
        self.print(f"SCALAR_STATE: {text(self.bias)} {text(self.gain)} {self.count} "
                   f"{int(self.active)} {self.label}")
