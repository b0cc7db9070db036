"""BlackBox: a placeholder with user-named ports."""
import re

from ikaros.module import RESERVED, Module, Parameter, attribute_name


def _names(text):
    text = (text or "").strip()
    if text in ("", "None"):
        return []
    return [n.strip() for n in re.split(r"[;,]", text) if n.strip()]


class BlackBox(Module):
    """A placeholder for sketching an architecture before its modules exist. ``ins`` and
    ``outs`` list the names of its inputs and outputs, separated by ``;`` (or ``,``). It
    computes nothing: every output is 0 and has the shape of the first input (one element
    when there is no connected input). Inputs may be left unconnected. With ``debug`` the
    module prints its inputs on every tick."""

    ins = Parameter(None, "the names of the inputs, separated by ;", type="string")
    outs = Parameter(None, "the names of the outputs, separated by ;", type="string")
    debug = Parameter(False, "print the inputs on every tick")

    def configure(self):
        self._ins = _names(self.ins)
        self._outs = _names(self.outs)
        taken = set(RESERVED) | {"ins", "outs", "debug"}
        seen = set()
        for name in self._ins + self._outs:
            attr = attribute_name(name)
            if name in RESERVED or attr in taken or attr.startswith("_"):
                raise ValueError(f'BlackBox: "{name}" cannot be used as a port name')
            if name in seen:
                raise ValueError(f'BlackBox: the port name "{name}" is given twice')
            seen.add(name)
        for name in self._ins:
            self.add_input(name, optional=True, description="a placeholder input")
        for name in self._outs:
            self.add_output(name, description="a placeholder output; always 0")

    def set_sizes(self):
        if not self._outs:
            return
        shape = self.input_shape(self._ins[0]) if self._ins else ()
        if shape is None:
            return
        for name in self._outs:
            self.set_output_shape(name, shape if shape else (1,))

    def tick(self):
        if self.debug:
            for name in self._ins:
                x = getattr(self, attribute_name(name))
                values = "unconnected" if x is None else " ".join(f"{v:g}" for v in x.flat)
                self.print(f"{name}: {values}")
