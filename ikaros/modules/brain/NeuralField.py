"""NeuralField: a generic scalar neural field."""
from ._nucleus import ScalarNucleus


class NeuralField(ScalarNucleus):
    """A generic scalar neural field, computed like Nucleus: the state x follows the drive a =
    phi * E / (1 + psi * S) - chi * I, where E, I and S pool the EXCITATION, INHIBITION and
    SHUNTING_INHIBITION inputs (the mean of their elements with ``scale``, else the sum;
    unconnected inputs give 0, a negative shunting term counts as 0): x += epsilon * (a - x)
    each tick from x = 0, and OUTPUT = alpha + beta * f(x) with f(x) = atan(x) / atan(1) for
    x > 0 and 0 otherwise. Inhibition is weighted by chi (the Ikaros 2 code used psi)."""
