"""MemorySequencer: replays a fixed one-hot sequence for each input."""
import numpy as np

from ikaros.module import Input, Module, Output

SEQUENCE = 10       # length of each stored sequence
SIZE = 80           # size of the output


class MemorySequencer(Module):
    """A stand-in for a recurrent memory (from the 2020 decision model). Every input pattern
    k = argmax(INPUT) has a stored sequence of 10 one-hot states, positions 10k .. 10k+9 of
    the 80-element OUTPUT. When INPUT changes (from what it was on the previous tick, which
    in init is all 0) the sequence of the new pattern starts: OUTPUT is one-hot at 10k, then
    10k+1 on the next tick and so on; after the tenth state it starts over, so the sequence
    repeats while the input stays. Before any change OUTPUT is all 0. States past the end of
    OUTPUT (k >= 8) are not shown (this project's reading is that Ikaros 2 writes past the
    end of its arrays there; its golden files, which this class reproduces, have no such
    case). Ikaros 3 has no MemorySequencer."""

    INPUT = Input("the pattern; its largest element selects the sequence", flatten=True)
    OUTPUT = Output("the current state of the sequence, one-hot", size=str(SIZE))

    def init(self):
        self._last = np.zeros(self.INPUT.size, dtype=np.float32)
        self._counter = 0           # 0: nothing to replay; else 1 + steps since the start
        self._index = 0
        self._warned = False
        self.OUTPUT[...] = 0

    def tick(self):
        self.OUTPUT[...] = 0
        if np.any(self.INPUT != self._last) or self._counter > SEQUENCE:
            self._counter = 1
            self._index = SEQUENCE * int(np.argmax(self.INPUT))
        if self._counter:
            if self._index < SIZE:
                self.OUTPUT[self._index] = 1
            elif not self._warned:
                self._warned = True
                self.warning(f"pattern {self._index // SEQUENCE} has no room in the "
                             f"{SIZE}-element output; it is not shown")
            self._counter += 1
            self._index += 1
        self._last[...] = self.INPUT
