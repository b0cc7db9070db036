"""Protocol: Ikaros 3's placeholder for a conditioning protocol (it computes nothing)."""
from ikaros.module import Module, Output, Parameter


class Protocol(Module):
    """Ikaros 3 ships this class as a stub: its tick does nothing, so STIMULUS and REWARD
    stay 0 and the parameters have no effect; the same here, so that a model that contains
    it builds and runs as in Ikaros 3. For stimulus sequences, see TimeSeries or
    InputFile."""

    CS_duration = Parameter(0.1, "unused, as in Ikaros 3")
    US_duration = Parameter(0.1, "unused, as in Ikaros 3")
    ISI = Parameter(0.1, "unused, as in Ikaros 3")
    ITI = Parameter(1.0, "unused, as in Ikaros 3")
    ITI_variation = Parameter(1.0, "unused, as in Ikaros 3")
    trials = Parameter(10.0, "unused, as in Ikaros 3")
    STIMULUS = Output("always 0", size="4")
    REWARD = Output("always 0", size="1")
