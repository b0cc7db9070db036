"""ServoConnector: re-maps, inverts and offsets a vector of servo values."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class ServoConnector(Module):
    """Re-maps a servo vector: OUTPUT[i] = b·(a·INPUT[connector[i] − 1] + offset[i]), where a is
    −1 when ``pre_inverted[i]`` is 1 (else 1) and b likewise for ``post_inverted[i]``.
    ``connector`` is 1-based; 0, or an index past the end of INPUT, gives an output of 0; an
    empty ``connector`` connects output i to input i. Missing entries of ``pre_inverted``,
    ``post_inverted`` and ``offset`` count as 0. OUTPUT has ``output_size`` elements (10 in
    an Ikaros 2 file, as there); in an Ikaros 3 file, where the parameter is gone and OUTPUT has
    INPUT's size, ``output_size`` is 0: INPUT's size."""

    connector = Parameter("", "for each output, the 1-based index of the input element it takes", type="array")
    pre_inverted = Parameter("", "1 where the input is negated before the offset is added", type="array")
    post_inverted = Parameter("", "1 where the result is negated after the offset is added", type="array")
    offset = Parameter("", "added to each (possibly negated) input", type="array")
    output_size = Parameter(10, "number of outputs (0: as many as INPUT has; the default in an Ikaros 3 file)",
                            type="int", range=(0, None), default_v3=0)

    INPUT = Input("the servo values")
    OUTPUT = Output("the re-mapped values")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if int(self.output_size) > 0:
            self.set_output_shape("OUTPUT", int(self.output_size))
        elif shape is not None:
            self.set_output_shape("OUTPUT", int(np.prod(shape)))

    def init(self):
        self._flat_input = self.INPUT.reshape(-1)

    def _per_output(self, values, fill=0.0):
        values = np.asarray(values, dtype=np.float64).reshape(-1)
        out = np.full(self.OUTPUT.size, fill)
        out[:min(values.size, out.size)] = values[:out.size]
        return out

    def tick(self):
        n = self.OUTPUT.size
        connector = np.asarray(self.connector, dtype=np.int64).reshape(-1)
        index = self._per_output(connector, 0).astype(np.int64) if connector.size else np.arange(1, n + 1)
        valid = (index >= 1) & (index <= self._flat_input.size)
        values = np.where(valid, self._flat_input[np.clip(index - 1, 0, max(self._flat_input.size - 1, 0))], 0.0)
        pre = np.where(self._per_output(self.pre_inverted) != 0, -1.0, 1.0)
        post = np.where(self._per_output(self.post_inverted) != 0, -1.0, 1.0)
        result = post * (pre * values + self._per_output(self.offset))
        self.OUTPUT.reshape(-1)[...] = np.where(valid, result, 0.0)
