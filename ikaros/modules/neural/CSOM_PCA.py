"""CSOM_PCA: a convolutional self-organising map with a PCA-like (Oja) learning rule."""
from ikaros.module import Parameter

from ._csom import StreamSOM


class CSOM_PCA(StreamSOM):
    """A convolutional self-organising map whose units learn principal components: one map of
    som_size_y x som_size_x units, each with a weight vector the size of a receptive field, is
    applied to every rf_size_y x rf_size_x receptive field of INPUT (stepping ``rf_inc``;
    blocks and spans as in CSOM). A unit's activity y is the dot product of its weights with
    the field (weighted by a quadratic arbor when ``use_arbor`` is set) and the best unit is
    the one with the largest |y| (a field and its negative have the same component). Each unit
    learns by Oja's rule dw = alpha * h * y * (x - y w) / (number of fields), h = exp(-g^2 / 2
    s^2) with g its distance on the map (wrapping on a torus) to the best unit and s = sigma *
    hypot(som_size_x/2, som_size_y/2), so its weights tend to a unit-length principal direction
    of the fields it wins and neighbouring units get similar directions. The weights start as
    random unit vectors (the same ``seed`` gives the same run); alpha and sigma decay after
    each tick between their min and max. RECONSTRUCTION puts back at every field the weights of
    the unit with the largest |TOP_DOWN| times that value (the best unit times its activity
    when TOP_DOWN is not connected), averaged where fields overlap; ERROR is the RMS difference
    between the fields and that reconstruction by their best unit. Extensions of Ikaros 2: the
    sigma parameters and ``seed``; ``activity_inc_x``, ``activity_inc_y``, ``update_algo``
    and ``border_multiplier`` have no effect here. The class is not in Ikaros 3, and the
    golden files have no case of it (its weights are random): these formulas are this
    project's reading of the catalogue's summary, and the random numbers come from NumPy's
    generator, not the original's."""

    activity_inc_x = Parameter(1, "no effect here (Ikaros 2: activity field increment)")
    activity_inc_y = Parameter(1, "no effect here (Ikaros 2: activity field increment)")
    use_arbor = Parameter(False, "weight the receptive field with a quadratic arbor function "
                          "that falls to 0 at its edge")
    update_algo = Parameter(0, "0: iterative, 1: matrix multiplication; both give the same "
                            "result here")
    border_multiplier = Parameter(1, "no effect here (Ikaros 2: a border for spans)")

    linear = True
