"""WilsonCowan: an excitatory–inhibitory pair of rate populations (Ikaros 3)."""
import math

from ikaros.module import Input, Module, Output, Parameter


def _sigmoid(drive: float, gain: float, midpoint: float, maximum: float) -> float:
    return maximum / (1 + math.exp(min(60.0, max(-60.0, -gain * (drive - midpoint)))))


class WilsonCowan(Module):
    """The Wilson–Cowan pair of Ikaros 3 (there a group class of RatePopulation, Scale,
    Add, Subtract, Clip, Multiply and Constant modules; here one module computing the same
    numbers). With E′ and I′ the inner rates of the previous tick (0 on the first tick,
    whatever the initial rates) and P, Q the external excitation and inhibition of this
    tick: drive_E = w_EE·E′ + P − w_IE·I′ and drive_I = w_EI·E′ + Q − w_II·I′; the sigmoid
    responses are S = M/(1 + e^(−g·(drive − θ))) (the exponent clamped to ±60); the
    availability is a = clip(k − r·rate′, 0, k), used as A = 1 + model·(a − 1) (model 0:
    the standard equations, 1: with refractoriness); the targets are T = A·S and the inner
    rates clamp(T, 0, M). The outputs are the inner rates and targets **of the previous
    tick** (0 on the first), as the original's group connects them with delay 1. The time
    constants and initial rates have no effect, because the original's RatePopulation
    makes its output the target every tick (see RatePopulation). New in Ikaros 3."""

    model = Parameter(1.0, "0: standard; 1: refractory (values in between interpolate)")
    excitatory_time_constant = Parameter(0.01, "no effect, as in Ikaros 3 (s)")
    inhibitory_time_constant = Parameter(0.01, "no effect, as in Ikaros 3 (s)")
    excitatory_self_weight = Parameter(0.8, "w_EE")
    inhibitory_to_excitatory_weight = Parameter(0.6, "w_IE")
    excitatory_to_inhibitory_weight = Parameter(0.7, "w_EI")
    inhibitory_self_weight = Parameter(0.4, "w_II")
    excitatory_sigmoid_gain = Parameter(0.15, "g_E")
    inhibitory_sigmoid_gain = Parameter(0.15, "g_I")
    excitatory_sigmoid_midpoint = Parameter(10.0, "θ_E")
    inhibitory_sigmoid_midpoint = Parameter(10.0, "θ_I")
    excitatory_maximum_response = Parameter(100.0, "M_E")
    inhibitory_maximum_response = Parameter(100.0, "M_I")
    excitatory_response_maximum = Parameter(1.0, "k_E, the largest availability")
    inhibitory_response_maximum = Parameter(1.0, "k_I, the largest availability")
    excitatory_refractory_period = Parameter(0.002, "r_E")
    inhibitory_refractory_period = Parameter(0.002, "r_I")
    initial_excitatory_rate = Parameter(0.0, "no effect, as in Ikaros 3")
    initial_inhibitory_rate = Parameter(0.0, "no effect, as in Ikaros 3")
    EXTERNAL_EXCITATION = Input("P, one element", flatten=True)
    EXTERNAL_INHIBITION = Input("Q, one element", flatten=True)
    EXCITATORY_RATE = Output("the excitatory rate of the previous tick", size="1")
    INHIBITORY_RATE = Output("the inhibitory rate of the previous tick", size="1")
    EXCITATORY_TARGET = Output("the excitatory target of the previous tick", size="1")
    INHIBITORY_TARGET = Output("the inhibitory target of the previous tick", size="1")

    def init(self):
        for name in ("EXTERNAL_EXCITATION", "EXTERNAL_INHIBITION"):
            if getattr(self, name).size != 1:
                self.fatal_error(f"{name} must have one element, not "
                                 f"{getattr(self, name).size}")
        self._rates = (0.0, 0.0)
        self._last = (0.0, 0.0, 0.0, 0.0)

    def _target(self, drive, rate, gain, midpoint, maximum, k, r):
        available = min(max(k - r * rate, 0.0), k)
        return (1 + self.model * (available - 1)) * _sigmoid(drive, gain, midpoint, maximum)

    def tick(self):
        e, i = self._rates
        p, q = float(self.EXTERNAL_EXCITATION[0]), float(self.EXTERNAL_INHIBITION[0])
        drive_e = self.excitatory_self_weight * e + p - self.inhibitory_to_excitatory_weight * i
        drive_i = self.excitatory_to_inhibitory_weight * e + q - self.inhibitory_self_weight * i
        t_e = self._target(drive_e, e, self.excitatory_sigmoid_gain,
                           self.excitatory_sigmoid_midpoint, self.excitatory_maximum_response,
                           self.excitatory_response_maximum, self.excitatory_refractory_period)
        t_i = self._target(drive_i, i, self.inhibitory_sigmoid_gain,
                           self.inhibitory_sigmoid_midpoint, self.inhibitory_maximum_response,
                           self.inhibitory_response_maximum, self.inhibitory_refractory_period)
        (self.EXCITATORY_RATE[0], self.INHIBITORY_RATE[0], self.EXCITATORY_TARGET[0],
         self.INHIBITORY_TARGET[0]) = self._last
        self._rates = (min(max(t_e, 0.0), self.excitatory_maximum_response),
                       min(max(t_i, 0.0), self.inhibitory_maximum_response))
        self._last = self._rates + (t_e, t_i)
