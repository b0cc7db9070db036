"""Nucleus: a generic brain nucleus."""
from ._nucleus import ScalarNucleus


class Nucleus(ScalarNucleus):
    """A generic brain nucleus: one unit whose state x follows its drive a = phi * E / (1 +
    psi * S) - chi * I, where E, I and S pool the EXCITATION, INHIBITION and
    SHUNTING_INHIBITION inputs (the mean of their elements with ``scale``, else the sum; an
    unconnected input gives 0, a negative shunting term counts as 0). Each tick x += epsilon
    * (a - x), starting at 0, and OUTPUT = alpha + beta * f(x) with f(x) = atan(x) / atan(1)
    for x > 0 and 0 otherwise, so f(1) = 1 and f tends to 2. Ikaros 2 weighted the
    inhibition by psi and scaled it by the size of the excitation, and output 0 (not alpha)
    for x < 0; here chi weights the inhibition, which is scaled by its own size, and alpha is
    always the offset."""
