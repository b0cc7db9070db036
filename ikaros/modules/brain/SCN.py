"""SCN: the suprachiasmatic nucleus as a light-driven circadian oscillator."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

# Forger, Jewett & Kronauer (1999), with the parameter values of Serkh & Forger (2014)
MU = 0.23                  # stiffness of the van der Pol oscillator
K = 0.55                   # how much light shortens the period
G = 33.75                  # gain of the light drive
ALPHA0 = 0.05              # photoreceptor activation rate at I0, per minute
BETA = 0.0075              # photoreceptor recovery rate, per minute
P = 0.5                    # exponent of the light intensity
I0 = 9500.0                # reference illuminance, lux
PERIOD_CORRECTION = 0.99669   # so that the oscillator free-runs with the intrinsic period
MAX_STEP = 0.05            # hours: the longest Runge-Kutta step


def derivative(state: np.ndarray, lux: float, period: float) -> np.ndarray:
    """d(x, xc, n)/dt in units per hour at illuminance ``lux``."""
    x, xc, n = state
    alpha = ALPHA0 * (max(lux, 0.0) / I0) ** P
    drive = G * (1 - n) * alpha * (1 - 0.4 * x) * (1 - 0.4 * xc)
    return np.array([
        math.pi / 12 * (xc + drive),
        math.pi / 12 * (MU * (xc - 4 / 3 * xc ** 3)
                        - x * ((24 / (PERIOD_CORRECTION * period)) ** 2 + K * drive)),
        60 * (alpha * (1 - n) - BETA * n)])


class SCN(Module):
    """The suprachiasmatic nucleus, the brain's circadian clock, as the light-driven
    limit-cycle oscillator of Forger, Jewett & Kronauer (1999), "A simpler model of the
    human circadian pacemaker", J. Biol. Rhythms 14(6): 532-537, with the parameter values
    of Serkh & Forger (2014), PLoS Comput. Biol. 10(4): e1003523: a van der Pol oscillator
    (x, xc) driven by light through a photoreceptor process n,

        dx/dt  = pi/12 (xc + B)
        dxc/dt = pi/12 (mu (xc - 4/3 xc^3) - x ((24 / (0.99669 tau))^2 + k B))
        dn/dt  = 60 (alpha (1 - n) - beta n),   alpha = alpha0 (I / I0)^p
        B      = G (1 - n) alpha (1 - 0.4 x) (1 - 0.4 xc)

    with t in hours, mu 0.23, k 0.55, G 33.75, alpha0 0.05, beta 0.0075, p 0.5 and I0 9500
    lux. The intrinsic period tau is 1 / ``frequency`` seconds (the default, 1/90000 Hz, is
    25 hours). Time is the model's: each tick advances it by tick_duration seconds (a
    tick_duration of 600 runs ten minutes a tick), integrated by the classic fourth-order
    Runge-Kutta method in steps of at most 3 minutes, the light held for the tick. INPUT is
    the light, its mean taken, where 1 stands for ``max_lux`` lux. OUTPUT is x (its minimum
    marks the minimum of the core body temperature), DIFF its change over the tick. It
    starts at x = 0, xc = 1, n = 0. The original's class is known only by its interface
    (INPUT, OUTPUT, DIFF and frequency): the model is this project's choice."""

    frequency = Parameter(0.00001111111111, "the free-running frequency in Hz (the "
                          "inverse of the intrinsic period)", range=(0, None))
    max_lux = Parameter(10000.0, "the illuminance in lux that an INPUT of 1 stands for",
                        range=(0, None))
    INPUT = Input("the light, 0 (dark) to 1 (max_lux); the mean of its elements",
                  flatten=True)
    OUTPUT = Output("the oscillator's x", size="1")
    DIFF = Output("the change of x over the tick", size="1")

    state = ("x", "xc", "n")

    def init(self):
        if self.frequency <= 0:
            raise ValueError(f"frequency must be above 0, not {self.frequency}")
        self.x, self.xc, self.n = 0.0, 1.0, 0.0
        self.OUTPUT[0] = self.x

    def tick(self):
        lux = self.max_lux * max(float(np.mean(self.INPUT)), 0.0)
        period = 1 / (3600 * self.frequency)
        hours = self.clock.tick_duration / 3600
        steps = max(1, math.ceil(hours / MAX_STEP))
        h = hours / steps
        state = np.array([self.x, self.xc, self.n])
        for _ in range(steps):
            k1 = derivative(state, lux, period)
            k2 = derivative(state + h / 2 * k1, lux, period)
            k3 = derivative(state + h / 2 * k2, lux, period)
            k4 = derivative(state + h * k3, lux, period)
            state = state + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        self.DIFF[0] = state[0] - self.x
        self.x, self.xc, self.n = (float(v) for v in state)
        self.OUTPUT[0] = self.x
