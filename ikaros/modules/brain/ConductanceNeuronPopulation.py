"""ConductanceNeuronPopulation: Hodgkin–Huxley or Morris–Lecar neurons (Ikaros 3)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from . import _conductance as eq
from ._conductance_kernels import HH_PARAMETERS, ML_PARAMETERS, kernels


class ConductanceNeuronPopulation(Module):
    """Conductance-based neurons, integrated with the classical Runge–Kutta method in
    ceil(tick_duration / maximum_internal_step) equal sub-steps, the values rounded to
    float32 after each (as Ikaros 3 does). The applied current is CURRENT plus the synaptic
    current g_e·(E_e − V) + g_i·(E_i − V) of EXCITATORY_CONDUCTANCE and
    INHIBITORY_CONDUCTANCE (unconnected inputs count as 0), held for the tick; V is in mV
    and time in seconds. ``hodgkin_huxley``: the classic squid-axon equations with gates m,
    h, n (clamped to 0 ... 1 after each step; RECOVERY is n). ``morris_lecar``: calcium and
    potassium with recovery variable w (clamped to 0 ... 1; RECOVERY is w). A spike is
    counted on a sub-step where V crosses ``spike_threshold`` upwards. At the start and on
    RESET above 0 a neuron has V = initial_voltage and its gates at their steady states
    there. SPIKE_COUNT is the spikes of the tick, SPIKES 1 where it is above 0 and
    FIRING_RATE the count per second. New in Ikaros 3."""

    population_size = Parameter(1, "the number of neurons", type="int", range=(1, None))
    model = Parameter("hodgkin_huxley", "the neuron equations",
                      options="hodgkin_huxley/morris_lecar")
    initial_voltage = Parameter(-65.0, "V at the start and on RESET (mV)")
    spike_threshold = Parameter(0.0, "V crossing it upwards counts a spike (mV)")
    excitatory_reversal_potential = Parameter(0.0, "E_e (mV)")
    inhibitory_reversal_potential = Parameter(-80.0, "E_i (mV)")
    maximum_internal_step = Parameter(0.000025, "the largest integration sub-step (s)",
                                      range=(1e-9, None))
    hh_capacitance_density = Parameter(1.0, "membrane capacitance (µF/cm²)")
    hh_sodium_conductance = Parameter(120.0, "g_Na (mS/cm²)")
    hh_potassium_conductance = Parameter(36.0, "g_K (mS/cm²)")
    hh_leak_conductance = Parameter(0.3, "g_L (mS/cm²)")
    hh_sodium_reversal_potential = Parameter(50.0, "E_Na (mV)")
    hh_potassium_reversal_potential = Parameter(-77.0, "E_K (mV)")
    hh_leak_reversal_potential = Parameter(-54.387, "E_L (mV)")
    ml_capacitance_density = Parameter(20.0, "membrane capacitance (µF/cm²)")
    ml_calcium_conductance = Parameter(4.4, "g_Ca (mS/cm²)")
    ml_potassium_conductance = Parameter(8.0, "g_K (mS/cm²)")
    ml_leak_conductance = Parameter(2.0, "g_L (mS/cm²)")
    ml_calcium_reversal_potential = Parameter(120.0, "E_Ca (mV)")
    ml_potassium_reversal_potential = Parameter(-84.0, "E_K (mV)")
    ml_leak_reversal_potential = Parameter(-60.0, "E_L (mV)")
    ml_activation_midpoint = Parameter(-1.2, "V1 (mV)")
    ml_activation_slope = Parameter(18.0, "V2 (mV)")
    ml_recovery_midpoint = Parameter(2.0, "V3 (mV)")
    ml_recovery_slope = Parameter(30.0, "V4 (mV)")
    ml_recovery_time_constant = Parameter(0.025, "τ_w (s)")
    CURRENT = Input("applied current (µA/cm²)", optional=True, size="@population_size")
    EXCITATORY_CONDUCTANCE = Input("g_e (mS/cm²)", optional=True, size="@population_size")
    INHIBITORY_CONDUCTANCE = Input("g_i (mS/cm²)", optional=True, size="@population_size")
    RESET = Input("above 0 restarts a neuron", optional=True, size="@population_size")
    SPIKES = Output("1 where a neuron spiked this tick", shape="@population_size")
    SPIKE_COUNT = Output("the spikes of this tick", shape="@population_size")
    FIRING_RATE = Output("the spikes of this tick per second", shape="@population_size")
    VOLTAGE = Output("the membrane potential (mV)", shape="@population_size")
    RECOVERY = Output("n (Hodgkin–Huxley) or w (Morris–Lecar)", shape="@population_size")

    def init(self):
        if self.clock.tick_duration > 0.01:
            self.warning(f"tick_duration {self.clock.tick_duration} s is long for spiking "
                         "neurons (above 10 ms)")
        n = self.population_size
        self._gates = np.zeros((3, n), np.float32)      # m, h, n (Hodgkin–Huxley)
        self._restart(np.ones(n, bool))

    def _restart(self, where):
        V = np.float64(self.initial_voltage)
        self.VOLTAGE[where] = V
        if self.model == "hodgkin_huxley":
            m, h, n = eq.hh_steady_gates(V)
            self._gates[:, where] = np.array([m, h, n], np.float32)[:, None]
            self.RECOVERY[where] = n
        else:
            self._gates[:, where] = 0
            self.RECOVERY[where] = eq.ml_steady_recovery(self, V)

    def _input(self, name):
        x = getattr(self, name)
        return np.zeros(self.population_size) if x is None else x.astype(np.float64)

    def tick(self):
        T = self.clock.tick_duration
        steps = max(1, math.ceil(T / self.maximum_internal_step))
        dt = T / steps
        if self.RESET is not None and (self.RESET > 0).any():
            self._restart(self.RESET > 0)
        current = self._input("CURRENT")
        g_e, g_i = self._input("EXCITATORY_CONDUCTANCE"), self._input("INHIBITORY_CONDUCTANCE")
        hh = self.model == "hodgkin_huxley"
        count = np.zeros(self.population_size)
        compiled = kernels()
        if compiled is not None:
            self._compiled_steps(compiled, hh, current, g_e, g_i, steps, dt, count)
        else:
            self._steps(hh, current, g_e, g_i, steps, dt, count)
        self.SPIKE_COUNT[...] = count
        self.SPIKES[...] = count > 0
        self.FIRING_RATE[...] = count / T

    def _compiled_steps(self, compiled, hh, current, g_e, g_i, steps, dt, count):
        names = HH_PARAMETERS if hh else ML_PARAMETERS
        p = np.array([getattr(self, name) for name in names], np.float64)
        state = self._gates if hh else self.RECOVERY
        loop = compiled.hodgkin_huxley if hh else compiled.morris_lecar
        loop(self.VOLTAGE, state, current, g_e, g_i, float(self.excitatory_reversal_potential),
             float(self.inhibitory_reversal_potential), p, steps, dt,
             float(self.spike_threshold), count)
        if hh:
            self.RECOVERY[...] = self._gates[2]

    def _steps(self, hh, current, g_e, g_i, steps, dt, count):
        """The NumPy form: all neurons at once, sub-step by sub-step."""
        def synaptic(V):
            return g_e * (self.excitatory_reversal_potential - V) + \
                g_i * (self.inhibitory_reversal_potential - V)

        derivatives = (lambda s: eq.hh_derivatives(self, s, current, synaptic)) if hh else \
            (lambda s: eq.ml_derivatives(self, s, current, synaptic))
        for _ in range(steps):
            V = self.VOLTAGE.astype(np.float64)
            state = (V, *self._gates.astype(np.float64)) if hh else \
                (V, self.RECOVERY.astype(np.float64))
            new = eq.rk4(derivatives, state, dt)
            count += (V < self.spike_threshold) & (new[0] >= self.spike_threshold)
            self.VOLTAGE[...] = new[0]
            if hh:
                self._gates[...] = np.clip(np.array(new[1:]), 0, 1)
                self.RECOVERY[...] = self._gates[2]
            else:
                self.RECOVERY[...] = np.clip(new[1], 0, 1)
