"""NeuralField: a generic scalar neural field."""
from ._nucleus import ScalarNucleus


class NeuralField(ScalarNucleus):
    """A generic scalar neural field, computed like the Ikaros 2 Nucleus (Ikaros 2 lists
    NeuralField with Nucleus's activation but ships no class file for it, so it cannot run
    one; Ikaros 3 has none): the state x follows the drive a = phi * E / (1 + psi * S) - chi
    * I, where E, I and S pool the EXCITATION, INHIBITION and SHUNTING_INHIBITION inputs (the
    mean of their elements with ``scale``, else the sum; unconnected inputs give 0, a
    negative shunting term counts as 0): x += epsilon * (a - x) each tick from x = 0, and
    OUTPUT = alpha + beta * atan(x) / tan(1) while x > 0, else 0."""
