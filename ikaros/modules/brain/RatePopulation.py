"""RatePopulation: a population of rate units with a static activation function
(Ikaros 3)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class RatePopulation(Module):
    """Rate units. Each tick, per unit, the drive is INPUT + EXCITATION − INHIBITION +
    MODULATION + bias (unconnected inputs count as 0) and the target is ``linear``
    gain·drive or ``relu`` max(0, gain·drive), clamped to minimum_output ... maximum_output,
    or ``sigmoid`` min + (max − min)/(1 + e^(−gain·(drive − sigmoid_midpoint))) (the
    exponent clamped to ±60). RESET above 0 sets a unit's OUTPUT to initial_output.

    As in Ikaros 3 (``filtered="no"``, the default), OUTPUT is the target itself every tick
    and ACTIVATION stays 0: the original's first-order filter works on an ACTIVATION that
    shares OUTPUT's storage, so it cancels, and time_constant and initial_output have no
    effect after the first tick. ``filtered="yes"`` gives the behaviour the class describes:
    ACTIVATION is the target and OUTPUT follows it exactly as a first-order system,
    OUTPUT = target + (OUTPUT − target)·e^(−tick_duration/time_constant), starting at
    initial_output. New in Ikaros 3."""

    population_size = Parameter(1, "the number of units", type="int", range=(1, None))
    activation_function = Parameter("linear", "the static nonlinearity of the drive",
                                    options="linear/relu/sigmoid")
    time_constant = Parameter(0.02, "the time constant of OUTPUT following the target (s); "
                              "used with filtered=yes", range=(1e-6, None))
    gain = Parameter(1.0, "multiplies the drive")
    bias = Parameter(0.0, "added to the drive")
    sigmoid_midpoint = Parameter(0.0, "the drive at the sigmoid's half point")
    minimum_output = Parameter(0.0, "the smallest target and output")
    maximum_output = Parameter(100.0, "the largest target and output")
    initial_output = Parameter(0.0, "OUTPUT at the start and on RESET")
    filtered = Parameter(False, "yes: OUTPUT follows the target as a first-order system and "
                         "ACTIVATION is the target (the documented intent); no: as Ikaros 3 "
                         "computes, OUTPUT is the target and ACTIVATION 0")
    INPUT = Input("drive", optional=True, size="@population_size")
    EXCITATION = Input("drive added", optional=True, size="@population_size")
    INHIBITION = Input("drive subtracted", optional=True, size="@population_size")
    MODULATION = Input("drive added", optional=True, size="@population_size")
    RESET = Input("above 0 sets a unit's OUTPUT to initial_output", optional=True,
                  size="@population_size")
    OUTPUT = Output("the rate of each unit", shape="@population_size")
    ACTIVATION = Output("the target of each unit with filtered=yes; 0 otherwise (Ikaros 3)",
                        shape="@population_size")

    def init(self):
        if self.maximum_output < self.minimum_output:
            self.fatal_error(f"maximum_output ({self.maximum_output}) is below "
                             f"minimum_output ({self.minimum_output})")
        self._initial = min(max(self.initial_output, self.minimum_output), self.maximum_output)
        self.OUTPUT[...] = self._initial

    def _target(self, drive):
        lo, hi = self.minimum_output, self.maximum_output
        if self.activation_function == "sigmoid":
            z = np.clip(-self.gain * (drive - self.sigmoid_midpoint), -60, 60)
            return lo + (hi - lo) / (1 + np.exp(z))
        g = self.gain * drive
        if self.activation_function == "relu":
            g = np.maximum(g, 0)
        return np.clip(g, lo, hi)

    def tick(self):
        if self.RESET is not None:
            self.OUTPUT[self.RESET > 0] = self._initial
        drive = np.full(self.population_size, self.bias, np.float64)
        for name, sign in (("INPUT", 1), ("EXCITATION", 1), ("INHIBITION", -1),
                           ("MODULATION", 1)):
            x = getattr(self, name)
            if x is not None:
                drive += sign * x.reshape(-1)
        target = self._target(drive)
        if not self.filtered:
            self.OUTPUT[...] = target
            return
        decay = math.exp(-self.clock.tick_duration / self.time_constant)
        self.ACTIVATION[...] = target
        self.OUTPUT[...] = target + (self.OUTPUT - target) * decay
