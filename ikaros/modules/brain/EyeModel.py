"""EyeModel: pupil control."""
from ikaros.module import Input, Module, Output, Parameter


class EyeModel(Module):
    """A model of an eye's pupil. The dilator (weighted by the alpha-1a receptor
    sensitivity ``alpha1a``) and the sphincter (weighted by the muscarinic M3 sensitivity
    ``m3``) pull against each other: the target diameter is p = pupil_min + (pupil_max -
    pupil_min) * clip(amplifier * (alpha1a * D - m3 * S), 0, 1), where D and S are the means
    of PUPIL_DILATOR and PUPIL_SPHINCTER. PUPIL_DIAMETER starts at pupil_min and moves towards
    p by the fraction ``epsilon`` each tick (1: at once), so it stays within pupil_min..
    pupil_max. OUTPUT is (gaze x, gaze y, 0.1 * diameter) for display, the gaze taken from the
    first two elements of GAZE (0, 0 when unconnected). Ikaros 2 ignored m3, alpha1a and
    amplifier and started the diameter at 0."""

    pupil_min = Parameter(2.0, "the smallest pupil diameter (mm)")
    pupil_max = Parameter(8.0, "the largest pupil diameter (mm)")
    epsilon = Parameter(0.5, "fraction of the way to the target diameter moved each tick; 1 "
                         "means immediately", range=(0, 1))
    m3 = Parameter(1.0, "sensitivity of the sphincter's muscarinic (M3) receptors")
    alpha1a = Parameter(1.0, "sensitivity of the dilator's alpha-1a receptors")
    amplifier = Parameter(1.0, "gain of the dilator - sphincter difference")
    GAZE = Input("horizontal and vertical gaze direction (-1..1)", optional=True, flatten=True)
    PUPIL_SPHINCTER = Input("the constricting (parasympathetic) drive; its mean is used",
                            flatten=True)
    PUPIL_DILATOR = Input("the dilating (sympathetic) drive; its mean is used", flatten=True)
    PUPIL_DIAMETER = Output("the pupil diameter (mm)", size="1")
    OUTPUT = Output("for display: gaze x, gaze y and 0.1 * the pupil diameter", size="3")

    def init(self):
        self._d = float(self.pupil_min)
        self.PUPIL_DIAMETER[...] = self._d
        self.OUTPUT[...] = (0.0, 0.0, 0.1 * self._d)

    def tick(self):
        lo, hi = self.pupil_min, self.pupil_max
        drive = self.amplifier * (self.alpha1a * float(self.PUPIL_DILATOR.mean())
                                  - self.m3 * float(self.PUPIL_SPHINCTER.mean()))
        target = lo + (hi - lo) * min(max(drive, 0.0), 1.0)
        self._d += self.epsilon * (target - self._d)
        self.PUPIL_DIAMETER[...] = self._d
        if self.GAZE is not None:
            g = self.GAZE[:2]
            self.OUTPUT[:g.size] = g
        self.OUTPUT[2] = 0.1 * self._d
