"""IntegrateAndFirePopulation: current-driven LIF, EIF, AdEx or QIF neurons (Ikaros 3)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class IntegrateAndFirePopulation(Module):
    """Spiking neurons driven by the current I = INPUT + EXCITATION − INHIBITION (nA;
    unconnected inputs count as 0), held for the tick and integrated in
    ceil(tick_duration / maximum_internal_step) equal sub-steps, the values rounded to
    float32 after each (as Ikaros 3 does). ``lif``: V moves exactly towards rest + R·I with
    the membrane time constant. ``eif``, ``adex``, ``qif``: one classical Runge–Kutta step
    of dV/dt = R·I_m/τ with I_m = (rest − V)/R + I, plus Δ·e^min(20, (V − threshold)/Δ)/R
    (eif, adex), plus quadratic_gain·(V − rest)(V − threshold) (qif), minus the adaptation
    current w (adex, with dw/dt = (a·(V − rest)/1000 − w)/τ_w). When V reaches the
    threshold the neuron spikes: V = reset_potential for refractory_period seconds (no
    threshold test then; adex's w relaxes exactly towards a·(V − rest)/1000) and adex's w
    grows by spike_adaptation. RESET above 0 restarts a neuron (V = initial_potential, w
    and the refractory time 0). SPIKE_COUNT is the spikes of the tick, SPIKES 1 where it is
    above 0, FIRING_RATE the count per second; ADAPTATION is w (0 but for adex). A
    tick_duration above 10 ms gives a warning. New in Ikaros 3."""

    population_size = Parameter(1, "the number of neurons", type="int", range=(1, None))
    model = Parameter("lif", "the neuron equation", options="lif/eif/adex/qif")
    membrane_time_constant = Parameter(0.02, "the passive time constant τ (s)")
    membrane_resistance = Parameter(100.0, "R (MΩ): the current times R is in mV")
    resting_potential = Parameter(-65.0, "mV")
    threshold = Parameter(-50.0, "the spike threshold (mV)")
    reset_potential = Parameter(-65.0, "the potential after a spike (mV)")
    initial_potential = Parameter(-65.0, "the potential at the start and on RESET (mV)")
    refractory_period = Parameter(0.002, "the absolute refractory time (s)")
    slope_factor = Parameter(2.0, "Δ, the exponential sharpness of eif and adex (mV)")
    adaptation_time_constant = Parameter(0.1, "τ_w of adex (s)")
    subthreshold_adaptation = Parameter(4.0, "a, adex's subthreshold coupling (nS)")
    spike_adaptation = Parameter(0.08, "b, adex's adaptation jump per spike (nA)")
    quadratic_gain = Parameter(0.004, "the gain of qif's quadratic term")
    maximum_internal_step = Parameter(0.0001, "the largest integration sub-step (s)",
                                      range=(1e-9, None))
    INPUT = Input("current (nA)", optional=True, size="@population_size")
    EXCITATION = Input("current added (nA)", optional=True, size="@population_size")
    INHIBITION = Input("current subtracted (nA)", optional=True, size="@population_size")
    RESET = Input("above 0 restarts a neuron", optional=True, size="@population_size")
    SPIKES = Output("1 where a neuron spiked this tick", shape="@population_size")
    SPIKE_COUNT = Output("the spikes of this tick", shape="@population_size")
    FIRING_RATE = Output("the spikes of this tick per second", shape="@population_size")
    VOLTAGE = Output("the membrane potential (mV)", shape="@population_size")
    ADAPTATION = Output("the adaptation current w of adex (nA); 0 for the others",
                        shape="@population_size")

    def init(self):
        if self.clock.tick_duration > 0.01:
            self.warning(f"tick_duration {self.clock.tick_duration} s is long for spiking "
                         "neurons (above 10 ms)")
        self.VOLTAGE[...] = self.initial_potential
        self.ADAPTATION[...] = 0
        self._refractory = np.zeros(self.population_size, np.float32)

    def _derivatives(self, V, w, current):
        """dV/dt and dw/dt of eif, adex and qif (float64)."""
        R, tau, rest, theta = (self.membrane_resistance, self.membrane_time_constant,
                               self.resting_potential, self.threshold)
        i_m = (rest - V) / R + current
        if self.model in ("eif", "adex"):
            delta = self.slope_factor
            i_m = i_m + delta * np.exp(np.minimum(20.0, (V - theta) / delta)) / R
        if self.model == "qif":
            i_m = i_m + self.quadratic_gain * (V - rest) * (V - theta)
        if self.model == "adex":
            i_m = i_m - w
            dw = (self.subthreshold_adaptation * (V - rest) / 1000.0 - w) / \
                self.adaptation_time_constant
        else:
            dw = np.zeros_like(V)
        C = 1000.0 * tau / R
        return 1000.0 * i_m / C, dw

    def _step(self, V, w, current, dt):
        """One sub-step of the neurons that are not refractory (float64 in, float64 out)."""
        if self.model == "lif":
            v_inf = self.resting_potential + self.membrane_resistance * current
            return v_inf + (V - v_inf) * math.exp(-dt / self.membrane_time_constant), w
        k1v, k1w = self._derivatives(V, w, current)
        k2v, k2w = self._derivatives(V + dt / 2 * k1v, w + dt / 2 * k1w, current)
        k3v, k3w = self._derivatives(V + dt / 2 * k2v, w + dt / 2 * k2w, current)
        k4v, k4w = self._derivatives(V + dt * k3v, w + dt * k3w, current)
        return (V + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v),
                w + dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w))

    def tick(self):
        n, T = self.population_size, self.clock.tick_duration
        steps = max(1, math.ceil(T / self.maximum_internal_step))
        dt = T / steps
        V, w, left = self.VOLTAGE, self.ADAPTATION, self._refractory
        if self.RESET is not None:
            restart = self.RESET > 0
            V[restart], w[restart], left[restart] = self.initial_potential, 0, 0
        current = np.zeros(n)
        for name, sign in (("INPUT", 1), ("EXCITATION", 1), ("INHIBITION", -1)):
            x = getattr(self, name)
            if x is not None:
                current += sign * x.reshape(-1).astype(np.float64)
        count = np.zeros(n)
        adex = self.model == "adex"
        relax = math.exp(-dt / self.adaptation_time_constant)
        for _ in range(steps):
            refractory = left > 0
            v_new, w_new = self._step(V.astype(np.float64), w.astype(np.float64), current, dt)
            if refractory.any():
                left[refractory] = np.maximum(0, left[refractory] - np.float32(dt))
                v_new[refractory] = self.reset_potential
                if adex:
                    target = self.subthreshold_adaptation * (self.reset_potential -
                                                             self.resting_potential) / 1000.0
                    w_ref = w[refractory].astype(np.float64)
                    w_new[refractory] = target + (w_ref - target) * relax
            spike = ~refractory & (v_new >= self.threshold)
            count += spike
            v_new[spike] = self.reset_potential
            left[spike] = self.refractory_period
            if adex:
                w_new[spike] += self.spike_adaptation
            V[...] = v_new
            w[...] = w_new if adex else 0
        self.SPIKE_COUNT[...] = count
        self.SPIKES[...] = count > 0
        self.FIRING_RATE[...] = count / T
