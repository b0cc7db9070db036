"""Cerebellum: Ikaros 3's placeholder cerebellum class (it computes nothing)."""
from ikaros.module import Input, Module, Output, Parameter


class Cerebellum(Module):
    """Ikaros 3 ships this class as a stub: it takes INPUT, STATE and TARGET, never writes
    OUTPUT (which stays 0) and uses none of its parameters; the same here, so that a model
    that contains it builds and runs as in Ikaros 3. (The original also writes 0 into its
    STATE input buffer each tick, which may reach the source over a zero-delay connection;
    a module here never writes its inputs, so that side effect is not reproduced.) For a
    cerebellar model that learns, see Delta with ``output="error"``."""

    learning_rate = Parameter(0.1, "unused, as in Ikaros 3")
    isi_mu = Parameter(0.0, "unused, as in Ikaros 3")
    isi_sigma = Parameter(0.0, "unused, as in Ikaros 3")
    isi_tau = Parameter(0.0, "unused, as in Ikaros 3")
    INPUT = Input("unused", flatten=True)
    STATE = Input("unused", flatten=True)
    TARGET = Input("unused", flatten=True)
    OUTPUT = Output("always 0", size="1")
