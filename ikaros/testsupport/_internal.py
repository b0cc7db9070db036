"""The base of the test-only classes: marks every subclass internal."""
from ikaros.module import Module


class InternalModule(Module):
    """A module class hidden from class listings and the module reference."""

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        cls.description.internal = True


def text(value) -> str:
    """A parameter value as the test models expect it printed: numbers without a needless
    ``.0``, booleans as true/false, arrays as nested lists."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return f"{value:g}"
    if hasattr(value, "tolist"):
        return str(_numbers(value.tolist())).replace(" ", "")
    return str(value)


def _numbers(x):
    if isinstance(x, list):
        return [_numbers(v) for v in x]
    return int(x) if float(x).is_integer() else x


def first_tick(module) -> int:
    """The number of the first tick in the module's model file: 0 (Ikaros 2) or 1
    (Ikaros 3)."""
    return 1 if module.dialect == "3" else 0


def sequence(tick: int, offset: float = 0.0, first: int = 0) -> float:
    """What DelaySequenceSource output on ``tick``: tick + offset, and 0 before the first
    tick ``first`` (no history yet, or the value of init)."""
    return tick + offset if tick >= first else 0.0


def vector(tick: int, first: int = 0) -> list[float]:
    """What DelayVectorSource output on ``tick``: [tick, tick + 100], [0, 0] before the
    first tick ``first``."""
    return [tick, tick + 100.0] if tick >= first else [0.0, 0.0]


class WindowCheck(InternalModule):
    """The base of the delay-window sinks: ``expected()`` gives what INPUT must hold this
    tick; every tick INPUT is printed as ``WINDOW tick=t: values`` and compared; a
    difference is a fatal error naming both; at the end ``WINDOW OK`` is printed if
    every tick matched."""

    def init(self):
        self._failed = False
        self._ticks = 0

    def tick(self):
        import numpy as np
        t = self.clock.tick
        got = self.INPUT.reshape(-1)
        want = np.asarray(self.expected(t), dtype=np.float32).reshape(-1)
        self.print(f"WINDOW tick={t}: " + " ".join(f"{v:g}" for v in got.tolist()))
        self._ticks += 1
        if got.shape != want.shape or not np.array_equal(got, want):
            self._failed = True
            self.fatal_error(f"WINDOW MISMATCH at tick {t}: got {got.tolist()}, expected "
                             f"{want.tolist()}")

    def stop(self):
        if self._ticks and not self._failed:
            self.print("WINDOW OK")


def grown(tick: int, max_rows: int, columns: int, first: int = 0):
    """What DynamicMatrixSource output on ``tick``: ``tick % max_rows + 1`` rows of
    ``columns``, element [r, c] = 100 tick + 10 r + c; no rows before the first tick
    ``first``."""
    import numpy as np
    if tick < first:
        return np.zeros((0, columns), dtype=np.float32)
    rows = tick % max_rows + 1
    r, c = np.mgrid[0:rows, 0:columns]
    return (100 * tick + 10 * r + c).astype(np.float32)


def shape_text(shape) -> str:
    """A shape as the test models expect it printed: ``3x2``."""
    return "x".join(str(s) for s in shape)
