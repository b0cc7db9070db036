"""MidiFilter: routes MIDI messages to outputs by a table of (status, first, last) rows."""
import numpy as np

from ikaros.module import Input, Module, Parameter


class MidiFilter(Module):
    """Routes MIDI messages to outputs by the rows of ``filter``, each (status, min, max):
    row k makes the output OUTPUTk (OUTPUT1, OUTPUT2, ...) of max - min elements, and a
    message whose status byte equals the row's status and whose first data byte d (the note
    or controller number) lies in min <= d < max sets element d - min to its second data byte
    (the velocity or value, 0..127). Elements keep their latest value. So ``filter="176 0 8;
    144 36 52"`` gives the eight first controllers of channel 1 in OUTPUT1 and sixteen
    drum-pad notes in OUTPUT2. INPUT is one message (status, data 1, data 2), as
    MidiInterface's OUTPUT, or several such rows (MidiInterface's MESSAGES), taken in order;
    a row whose status is 0 is no message. A message seen again on the next tick with the same
    bytes is applied again (which changes nothing). ``debug`` prints every message that
    matches a row. The output names are this implementation's (the Ikaros 2 class made them in
    its code); a row whose max is not above its min, as the default ``0 0 0``, gives an output
    of one element that nothing sets."""

    filter = Parameter("0 0 0", "the filter table: one (status, min, max) row per output",
                       type="matrix")
    debug = Parameter(False, "print every message that matches a row")
    INPUT = Input("MIDI messages: (status, data 1, data 2) rows")

    def configure(self):
        table = np.atleast_2d(np.asarray(self.filter, dtype=float))
        if table.size == 0 or table.shape[1] != 3:
            raise ValueError(f"filter must have three columns (status, min, max); it has "
                             f"shape {table.shape}")
        self._rows = [(int(s), int(lo), int(hi)) for s, lo, hi in table]
        for k, (status, lo, hi) in enumerate(self._rows, 1):
            self.add_output(f"OUTPUT{k}", (max(hi - lo, 1),),
                            description=f"values of status {status}, numbers {lo} to {hi - 1}")

    def init(self):
        self._outputs = [getattr(self, f"OUTPUT{k}") for k in range(1, len(self._rows) + 1)]
        if self.INPUT.size % 3:
            raise ValueError(f"INPUT has {self.INPUT.size} elements: MIDI messages come in "
                             f"rows of three (status, data 1, data 2)")

    def tick(self):
        for status, number, value in self.INPUT.reshape(-1, 3):
            if status == 0:
                continue
            for (s, lo, hi), out in zip(self._rows, self._outputs):
                if status == s and lo <= number < hi:
                    out[int(number) - lo] = value
                    if self.debug:
                        self.print(f"({int(status)}, {int(number)}, {int(value)}) -> "
                                   f"element {int(number) - lo} of the row for status {s}")
