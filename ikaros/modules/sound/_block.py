"""The base of the sound-synthesis modules: one block of samples per tick, sample_rate ×
tick_duration of them, as Ikaros 3's audio classes declare (``size=@sample_rate*@tick_duration``:
the language's ``@tick_duration``, the model's tick duration or its default)."""
from __future__ import annotations

import numpy as np

from ikaros.module import Module, Output, Parameter


class AudioBlock(Module):
    """A module whose OUTPUT is one block of samples per tick: sample_rate × tick_duration
    samples, sized as Ikaros 3 declares it (``@sample_rate*@tick_duration``, where
    ``@tick_duration`` is the model's, or its default when the model sets none; a fraction
    of a sample is cut down, with a warning). A sample rate of 0 or below is a build error,
    as in Ikaros 3 (where the output's size becomes 0 and the model does not build)."""

    sample_rate = Parameter(0.0, "samples per second (usually set once on the top group); "
                            "0 does not build", fixed=True)
    OUTPUT = Output("this tick's block of samples, sample_rate × tick_duration of them",
                    shape="@sample_rate*@tick_duration")

    def configure(self):
        check_sample_rate(self.sample_rate)

    def init(self):
        self.rate = float(self.sample_rate)
        seconds = self.clock.tick_duration
        exact = self.rate * seconds
        if self.OUTPUT.size != whole_samples(exact):
            self.warning(f"the block has {self.OUTPUT.size} samples (a tick_duration set "
                         f"inside the model sizes it), but the model ticks every "
                         f"{seconds:g} s: sample_rate × {seconds:g} s = {exact:g} samples")
        else:
            warn_if_not_whole(self, self.rate, seconds)


def check_sample_rate(sample_rate: float) -> None:
    """A ValueError unless the sample rate is above 0."""
    if not sample_rate > 0:
        raise ValueError(f"sample_rate is {sample_rate:g}: set it to the samples per second "
                         f"(usually on the top group, e.g. sample_rate=\"44100\")")


def block_length(sample_rate: float, seconds: float) -> int:
    """The number of samples in ``seconds`` at ``sample_rate``: rounded when within a
    millionth of a whole number, else cut down; a rate of 0 or below, or no sample, is a
    ValueError."""
    check_sample_rate(sample_rate)
    exact = sample_rate * seconds
    n = whole_samples(exact)
    if n < 1:
        raise ValueError(f"sample_rate × {seconds:g} s = {exact:g}: a block needs at least "
                         f"one sample")
    return n


def whole_samples(exact: float) -> int:
    """A number of samples cut down to a whole number, except that one within a millionth
    of a whole number is that number (as the kernel sizes a shape expression)."""
    return round(exact) if abs(exact - round(exact)) <= 1e-6 else int(np.floor(exact))


def warn_if_not_whole(module: Module, sample_rate: float, seconds: float) -> None:
    """Warn (from init, so that the run's log has it) when a block is cut down."""
    exact = sample_rate * seconds
    if abs(exact - round(exact)) > 1e-6:
        module.warning(f"sample_rate × {seconds:g} s = {exact:g} is not a whole number of "
                       f"samples: a block has {block_length(sample_rate, seconds)}")


def per_sample(x: np.ndarray | None, n: int, default: float) -> np.ndarray:
    """An input as one value per sample of a block of ``n`` (float64): element i for sample
    i when the input is one-dimensional with n elements or more, else its first element for
    every sample; ``default`` when it is not connected (or empty)."""
    if x is None or x.size == 0:
        return np.full(n, default, np.float64)
    if x.ndim == 1 and x.size >= n:
        return x[:n].astype(np.float64)
    return np.full(n, float(x.flat[0]), np.float64)
