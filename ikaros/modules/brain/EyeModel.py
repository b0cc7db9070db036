"""EyeModel: pupil control."""
from ikaros.module import Input, Module, Output, Parameter


class EyeModel(Module):
    """A model of an eye's pupil, as Ikaros 2 computes it (Ikaros 3 has no EyeModel). The
    dilator (weighted by the alpha-1a receptor sensitivity ``alpha1a``) and the sphincter
    (weighted by the muscarinic M3 sensitivity ``m3``) pull against each other: the target
    diameter is p = pupil_min + (pupil_max - pupil_min) * clip(amplifier * (alpha1a * D - m3
    * S), 0, 1), where D and S are the first elements of PUPIL_DILATOR and PUPIL_SPHINCTER.
    PUPIL_DIAMETER starts at ``start_diameter`` (0, as in Ikaros 2, below pupil_min; set it
    to pupil_min for a pupil that starts at rest) and moves towards p by the fraction
    ``epsilon`` each tick (1: at once). OUTPUT is (gaze x, gaze y, diameter) for display,
    the gaze taken from the first two elements of GAZE (0, 0 when unconnected). The golden
    files of Ikaros 2 show the target, the first elements, the start at 0, epsilon and
    OUTPUT without GAZE; they do not show whether Ikaros 2 uses ``alpha1a`` and
    ``amplifier`` (none of their cases changes them), nor, for ``m3``, more than that m3 =
    2 agrees with them. This project uses all three as written above, and passes GAZE
    through as the Ikaros 2 class description says."""

    pupil_min = Parameter(2.0, "the smallest target diameter (mm)")
    pupil_max = Parameter(8.0, "the largest target diameter (mm)")
    epsilon = Parameter(0.5, "fraction of the way to the target diameter moved each tick; 1 "
                         "means immediately", range=(0, 1))
    m3 = Parameter(1.0, "sensitivity of the sphincter's muscarinic (M3) receptors")
    alpha1a = Parameter(1.0, "sensitivity of the dilator's alpha-1a receptors")
    amplifier = Parameter(1.0, "gain of the dilator - sphincter difference")
    start_diameter = Parameter(0.0, "the diameter before the first tick (Ikaros 2: 0)")
    GAZE = Input("horizontal and vertical gaze direction (-1..1)", optional=True, flatten=True)
    PUPIL_SPHINCTER = Input("the constricting (parasympathetic) drive; its first element is "
                            "used", flatten=True)
    PUPIL_DILATOR = Input("the dilating (sympathetic) drive; its first element is used",
                          flatten=True)
    PUPIL_DIAMETER = Output("the pupil diameter (mm)", size="1")
    OUTPUT = Output("for display: gaze x, gaze y and the pupil diameter", size="3")

    def init(self):
        self._d = float(self.start_diameter)
        self.PUPIL_DIAMETER[...] = self._d
        self.OUTPUT[...] = (0.0, 0.0, self._d)

    def tick(self):
        lo, hi = self.pupil_min, self.pupil_max
        dilator = float(self.PUPIL_DILATOR[0]) if self.PUPIL_DILATOR.size else 0.0
        sphincter = float(self.PUPIL_SPHINCTER[0]) if self.PUPIL_SPHINCTER.size else 0.0
        drive = self.amplifier * (self.alpha1a * dilator - self.m3 * sphincter)
        target = lo + (hi - lo) * min(max(drive, 0.0), 1.0)
        self._d += self.epsilon * (target - self._d)
        self.PUPIL_DIAMETER[...] = self._d
        if self.GAZE is not None:
            g = self.GAZE[:2]
            self.OUTPUT[:g.size] = g
        self.OUTPUT[2] = self._d
