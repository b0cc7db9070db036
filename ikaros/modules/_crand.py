"""The C library's ``rand()`` as Ikaros 2 draws from it on Linux (glibc), for the classes
whose Ikaros 2 values the golden files show to come from it (Perceptron's initial weights,
Trainer's random order, DataBuffer, EventTrigger).

Ikaros 2 calls ``rand()`` without seeding it, so every run of the original draws the same
numbers: glibc's sequence for seed 1 (1804289383, 846930886, 1681692777, ...). The original
has one such sequence per program, shared by all its modules in the order they draw; here
there is one per network (found through the clock that the network's modules share), so a
model with one drawing module gets the original's numbers exactly, and several drawing
modules share the sequence as they do in the original (in the order this kernel runs them).

glibc's ``rand()`` is an additive lagged Fibonacci generator (its TYPE_3, degree 31,
separation 3): the state is seeded with a Park-Miller sequence, the first 310 results are
thrown away, and each result is (r[i - 31] + r[i - 3]) mod 2**32 shifted right by one bit;
computed here from that published definition.
"""
import secrets
import weakref

import numpy as np

RAND_MAX = 2**31 - 1
_DEGREE, _SEPARATION, _DISCARD = 31, 3, 310
_RING = _DEGREE + _SEPARATION          # the values kept: r[k - 34] ... r[k - 1]


class CRand:
    """One ``rand()`` stream. ``seed`` as ``srand(seed)`` (0 is taken as 1, as glibc does);
    None is the unseeded program (seed 1); a negative seed draws a seed at random, so that
    every run differs."""

    def __init__(self, seed: int | None = None):
        if seed is None:
            seed = 1
        elif seed < 0:
            seed = secrets.randbelow(RAND_MAX) + 1
        seed = int(seed) % 2**32 or 1
        r = [seed]
        for _ in range(1, _DEGREE):
            # 16807 * r mod (2**31 - 1), computed on signed 32-bit values as glibc does
            hi, lo = divmod(_signed(r[-1]), 127773)
            word = 16807 * lo - 2836 * hi
            r.append(word + RAND_MAX if word < 0 else word)
        r += r[:_SEPARATION]                  # r[31], r[32], r[33] copy r[0], r[1], r[2]
        self._r = [v % 2**32 for v in r]
        self._k = _RING
        for _ in range(_DISCARD):
            self._next()

    def _next(self) -> int:
        r, k = self._r, self._k
        value = (r[(k - _DEGREE) % _RING] + r[(k - _SEPARATION) % _RING]) % 2**32
        r[k % _RING] = value
        self._k = k + 1
        return value

    def rand(self) -> int:
        """The next value of ``rand()``, 0 ... RAND_MAX."""
        return self._next() >> 1

    def uniform(self, low: float, high: float) -> float:
        """low + (high − low)·rand()/RAND_MAX: how the original draws a number in a range."""
        return low + (high - low) * self.rand() / RAND_MAX


def _signed(value: int) -> int:
    value %= 2**32
    return value - 2**32 if value >= 2**31 else value


_streams: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def network_rand(clock) -> CRand:
    """The unseeded rand() sequence of the network whose modules share ``clock``."""
    stream = _streams.get(clock)
    if stream is None:
        stream = _streams[clock] = CRand()
    return stream


def module_rand(module) -> CRand:
    """The rand() stream of a module with a ``seed`` parameter: the network's shared,
    unseeded one when the seed is unset, as the original draws; else one of its own seeded
    as ``srand(seed)`` does (negative: a different run every time)."""
    return network_rand(module.clock) if module.seed is None else CRand(module.seed)


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
