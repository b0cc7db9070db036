"""The C library's rand(), as the original Ikaros 2 draws its random numbers.

Ikaros 2's learning classes (Perceptron's initial weights, Trainer's random order) call the C
library's ``rand()`` without seeding it, so every run of the original draws the same numbers:
glibc's sequence for seed 1. The original has one such sequence per program, shared by all
its modules in the order they draw; here there is one per network (found through the clock
that the network's modules share), so a model with one drawing module gets the original's
numbers exactly, and several drawing modules share the sequence as they do in the original.

The generator is glibc's ``random_r`` of type 3 (an additive feedback generator over 31
words, whose first 310 outputs are discarded), computed from its published definition.
"""
import weakref

import numpy as np

RAND_MAX = 2147483647


class CRand:
    """glibc's rand() sequence from ``srand(seed)``."""

    def __init__(self, seed: int = 1):
        r = [seed & 0xFFFFFFFF]
        for i in range(1, 31):
            hi, lo = divmod(r[i - 1], 127773)
            word = 16807 * lo - 2836 * hi       # 16807 * r mod (2^31 - 1), Schrage's way
            r.append(word + RAND_MAX if word < 0 else word)
        r += r[:3]                              # r[31..33]
        for i in range(34, 344):
            r.append((r[i - 31] + r[i - 3]) & 0xFFFFFFFF)
        self._ring = r[-34:]                    # the last 34 words: enough for the lags
        self._at = 0

    def rand(self) -> int:
        """The next value of rand(): 0 .. RAND_MAX."""
        ring, i = self._ring, self._at
        word = (ring[(i + 3) % 34] + ring[(i + 31) % 34]) & 0xFFFFFFFF   # r[n-31] + r[n-3]
        ring[i] = word
        self._at = (i + 1) % 34
        return word >> 1

    def uniform(self, low: float, high: float) -> float:
        """low + (high − low)·rand()/RAND_MAX: how the original draws a number in a range."""
        return low + (high - low) * self.rand() / RAND_MAX


_streams: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def network_rand(clock) -> CRand:
    """The rand() sequence of the network whose modules share ``clock``."""
    stream = _streams.get(clock)
    if stream is None:
        stream = _streams[clock] = CRand()
    return stream


def uses_crand(module) -> bool:
    """Whether a module with a ``seed`` parameter draws from the network's rand() sequence:
    with the seed unset (or 0) in an Ikaros 2 file, as the original draws. Otherwise it
    draws from NumPy's generator with that seed (below 0, or unset in an Ikaros 3 file: a
    new seed every run)."""
    return not module.seed and module.dialect != "3"


def numpy_generator(module) -> np.random.Generator:
    """NumPy's generator for a module's ``seed`` when it does not use rand()."""
    return np.random.default_rng(module.seed if module.seed and module.seed > 0 else None)


def random_rows(module):
    """A function giving a random index below n for a module with a ``seed`` parameter:
    rand() % n as the original draws (see ``uses_crand``), or from NumPy's generator."""
    if uses_crand(module):
        stream = network_rand(module.clock)
        return lambda n: stream.rand() % n
    rng = numpy_generator(module)
    return lambda n: int(rng.integers(n))
