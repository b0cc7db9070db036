"""The random generator of the classes that take a ``seed`` (Noise, Randomizer)."""
import numpy as np


def generator(seed) -> np.random.Generator:
    """NumPy's generator for a ``seed`` parameter: a seed above 0 gives the same numbers on
    every run; unset, 0 or negative (Ikaros 3's default -1) a different run every time."""
    return np.random.default_rng(seed if seed is not None and seed > 0 else None)
