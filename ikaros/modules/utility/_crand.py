"""The C library's ``rand()`` as Ikaros 2 draws from it on Linux (glibc), for the classes
whose Ikaros 2 values the golden files show to come from it (DataBuffer, EventTrigger).

glibc's ``rand()`` is an additive lagged Fibonacci generator (its TYPE_3, degree 31,
separation 3): the state is seeded with a Park-Miller sequence, the first 310 results are
thrown away, and each result is (r[i - 31] + r[i - 3]) mod 2**32 shifted right by one bit.
A program that never calls ``srand`` draws as if seeded with 1: 1804289383, 846930886,
1681692777, ...
"""
import secrets

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


def _signed(value: int) -> int:
    value %= 2**32
    return value - 2**32 if value >= 2**31 else value
