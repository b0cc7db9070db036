"""FFT: the discrete Fourier transform of a signal."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class FFT(Module):
    """Outputs the discrete Fourier transform of INPUT, unnormalised (X[k] = sum over n of
    x[n] exp(-2 pi i k n / N)), split into its real part on REAL_OUTPUT and its imaginary part
    on IM_OUTPUT. Both outputs have the shape of INPUT: a 1-D input gives its N-point
    spectrum, and a matrix is transformed row by row (along its last axis). Bin k is the
    frequency k / N cycles per element. As in Ikaros 2 (golden files) only bins 0 ... N / 2
    are given and the others are 0; ``bins="all"`` (this project's) gives every bin, those
    above N / 2 being the negative frequencies (for a real signal, the complex conjugates of
    the bins below). Any length works here; Ikaros 2's FFT library (AudioFFT) is made for
    powers of two, and the golden files hold only such lengths."""

    bins = Parameter("half", "half: bins 0 ... N / 2, the others 0 (Ikaros 2); all: every "
                     "bin", options="half/all")
    debug = Parameter(False, "print the input and the spectrum on every tick")
    INPUT = Input("the signal; a matrix is transformed row by row")
    REAL_OUTPUT = Output("the real part of the spectrum", size_set="INPUT")
    IM_OUTPUT = Output("the imaginary part of the spectrum", size_set="INPUT")

    def tick(self):
        spectrum = np.fft.fft(self.INPUT, axis=-1)
        if self.bins == "half":
            spectrum[..., spectrum.shape[-1] // 2 + 1:] = 0
        self.REAL_OUTPUT[...] = spectrum.real
        self.IM_OUTPUT[...] = spectrum.imag
        if self.debug:
            self.print(f"input {np.array2string(self.INPUT)} real "
                       f"{np.array2string(self.REAL_OUTPUT)} imaginary "
                       f"{np.array2string(self.IM_OUTPUT)}")
