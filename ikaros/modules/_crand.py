"""How the classes that draw as Ikaros 2 does (Perceptron's initial weights, Trainer's random
order, DataBuffer, EventTrigger, MazeGenerator, PlanarArm, Perception) choose their stream
of the C library's ``rand()`` (``ikaros.module.CRandom``: glibc's generator, which Ikaros 2
never seeds), or NumPy's generator where the original's numbers are not the point."""
import secrets

import numpy as np

from ikaros.module import RAND_MAX, CRandom


def module_rand(module) -> CRandom:
    """The rand() stream of a module with a ``seed`` parameter: the network's shared one
    (``module.c_random``, unseeded as the original's) when the seed is unset or 0; else one
    of its own seeded as ``srand(seed)`` does, a negative seed a random one (a different run
    every time)."""
    if not module.seed:
        return module.c_random
    return CRandom(module.seed if module.seed > 0 else secrets.randbelow(RAND_MAX) + 1)


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
        stream = module.c_random
        return lambda n: stream.rand() % n
    rng = numpy_generator(module)
    return lambda n: int(rng.integers(n))
