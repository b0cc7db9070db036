"""The C library's ``rand()`` as Ikaros 2 drew from it: GNU libc's generator, never seeded.

Ikaros 2 classes that make random choices (PlanarArm's target, Perception's gaze, ...) call
``rand()`` without seeding it, so on Linux every run draws the sequence of seed 1:
1804289383, 846930886, 1681692777, ... A network keeps one stream that its modules share
(``Module.c_random``), as a C program's modules share the library's, so a model whose
random classes draw in the original's order gets the original's numbers.

The generator is glibc's ``random_r`` of type 3 (a lagged additive generator over 34
words, r[i] = r[i-3] + r[i-31] mod 2^32, the output r[i] >> 1), seeded by the linear
congruence 16807 x mod (2^31 - 1) with its first 310 outputs discarded, as glibc does.
"""

RAND_MAX = 2147483647
_DEGREE, _SEPARATION, _DISCARD = 31, 3, 310


class CRandom:
    """One C ``rand()`` stream. ``rand()`` gives 0 … RAND_MAX, ``uniform()`` the fraction
    ``rand() / RAND_MAX`` (0 … 1, both included) that Ikaros 2 turns into a random number."""

    __slots__ = ("_state", "_front", "_rear")

    def __init__(self, seed: int = 1):
        self.seed(seed)

    def seed(self, seed: int) -> None:
        """Start again as ``srand(seed)`` does (0 counts as 1)."""
        word = (int(seed) & 0xFFFFFFFF) or 1
        state = [word]
        for _ in range(_DEGREE - 1):
            high, low = divmod(word, 127773)
            word = 16807 * low - 2836 * high
            if word < 0:
                word += RAND_MAX
            state.append(word)
        self._state = [w & 0xFFFFFFFF for w in state]
        self._front, self._rear = _SEPARATION, 0
        for _ in range(_DISCARD):
            self.rand()

    def rand(self) -> int:
        """The next number, 0 … RAND_MAX."""
        state, front, rear = self._state, self._front, self._rear
        state[front] = (state[front] + state[rear]) & 0xFFFFFFFF
        result = state[front] >> 1
        self._front = front + 1 if front + 1 < _DEGREE else 0
        self._rear = rear + 1 if rear + 1 < _DEGREE else 0
        return result

    def uniform(self) -> float:
        """``rand() / RAND_MAX``: a fraction 0 … 1."""
        return self.rand() / RAND_MAX
