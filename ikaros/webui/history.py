"""Every tick seen: a short per-tick history of the buffers that clients subscribe to as
``history`` (plots) or ``events`` (event rasters).

The UI draws 10-15 frames a second while the model may run thousands of ticks; a plot fed
one value per frame aliases fast signals into noise. ``Recorder.hook`` runs in the kernel's
thread after every tick and appends one row per subscribed buffer to a ring (a copy of a
few floats; it stops for that tick when the copying budget is spent, and the ticks it did
not record are reported as missed). Each data frame then carries what happened since the
frame before, per client:

- ``history``: every sample when there are at most ``points`` of them (the plot's width in
  pixels), otherwise a min/max envelope: ``points`` columns of equal tick spans, each with
  the smallest and largest value of every element within it, so that no peak is lost;
- ``events``: every (tick, element) whose value is above 0, as pairs, never thinned; these
  buffers are recorded on every tick even when the budget is spent (a row of a spike
  vector costs microseconds), so no event is lost while the client keeps up with the ring.
"""
from __future__ import annotations

import time

import numpy as np

HISTORY_FORMATS = ("history", "events")
MAX_FLOATS = 1 << 20          # values kept per buffer (4 MB of float32)
MIN_TICKS, MAX_TICKS = 256, 16384
DEFAULT_POINTS = 512
MAX_POINTS = 8192
MAX_EVENTS = 1 << 20          # pairs in one frame at most (the rest are counted as missed)
RETIRED_FLOATS = 8 * MAX_FLOATS   # values kept in rings no client subscribes to any more


class Ring:
    """The last ``capacity`` rows of one buffer, each labelled with its tick."""

    def __init__(self, src: np.ndarray, always: bool = False):
        self.src = src
        self.always = always                # recorded even when the budget is spent
        self.size = max(1, int(src.size))
        # an event buffer (spikes: a few values, rarely read whole) keeps as many ticks as
        # the value limit allows, so that a fast kernel loses none between two frames
        most = MAX_FLOATS if always else MAX_TICKS
        self.capacity = int(np.clip(MAX_FLOATS // self.size, MIN_TICKS, most))
        self.rows = np.zeros((self.capacity, self.size), np.float32)
        self.ticks = np.full(self.capacity, -1, np.int64)
        self.count = 0
        # a flat view made once (a buffer that is not contiguous is flattened each tick)
        self._flat = src.reshape(-1) if src.flags.c_contiguous else None

    def record(self, tick: int) -> None:
        last = (self.count - 1) % self.capacity
        if self.count and self.ticks[last] == tick:
            i = last                        # the hooks ran again for the same tick
        else:
            i = self.count % self.capacity
            self.count += 1
        if self.src.size:
            self.rows[i] = self._flat if self._flat is not None else self.src.reshape(-1)
        else:
            self.rows[i] = 0.0
        self.ticks[i] = tick

    @property
    def last_tick(self) -> int:
        """The tick of the newest row (-1 before the first)."""
        return int(self.ticks[(self.count - 1) % self.capacity]) if self.count else -1

    def since(self, tick: int) -> tuple[np.ndarray, np.ndarray]:
        """Copies of (ticks, rows) recorded after ``tick``, oldest first."""
        n = min(self.count, self.capacity)
        if n == 0:
            return np.empty(0, np.int64), np.empty((0, self.size), np.float32)
        order = (np.arange(self.count - n, self.count) % self.capacity)
        ticks = self.ticks[order]
        keep = ticks > tick
        return ticks[keep], self.rows[order[keep]]


class Recorder:
    """One ring per buffer subscribed with a history format (kernel side).

    A ring no client subscribes to any more is kept aside (up to ``RETIRED_FLOATS`` values,
    the most recently dropped first) and taken up again by a new subscription while no tick
    has run since it was dropped: a page reloaded, or a view opened again, on a paused model
    shows the ticks it showed before (and the present tick's value, should the copying
    budget have left it out)."""

    def __init__(self, net, budget: float):
        self.net = net
        self.budget = budget
        self.rings: dict[str, Ring] = {}
        self.retired: dict[str, tuple[Ring, int]] = {}  # path -> (ring, tick dropped at)
        self._split: tuple[tuple[Ring, ...], tuple[Ring, ...]] = ((), ())  # always, others
        self._start = 0                     # where the next tick begins (fair under budget)
        self.skipped = 0                    # rows not recorded for lack of time

    def set_sources(self, sources: dict[str, np.ndarray], events: set[str] = frozenset()
                    ) -> None:
        """Replace the buffers (server thread); a ring of an unchanged buffer is kept. The
        buffers in ``events`` are recorded every tick whatever the budget: no event is lost."""
        now = self.net.tick
        rings = {}
        for path, src in sources.items():
            old = self.rings.get(path)
            if old is None:
                old, dropped = self.retired.pop(path, (None, None))
                if dropped != now:
                    old = None                  # ticks ran unrecorded since it was dropped
                elif old.last_tick != now:
                    old.record(now)             # the budget left the last tick out
            keep = old is not None and old.src is src and old.always == (path in events)
            if not keep:
                # the value it has now is the first row: a page that reloads later shows
                # the tick this one started from (a model paused at tick 0 included)
                old = Ring(src, path in events)
                old.record(now)
            rings[path] = old
        for path, ring in self.rings.items():
            if path not in rings:
                self._retire(path, ring)
        self.rings = rings
        # one assignment: the hook sees the old rings or the new ones, never a mix
        self._split = (tuple(r for r in rings.values() if r.always),
                       tuple(r for r in rings.values() if not r.always))

    def _retire(self, path: str, ring: Ring) -> None:
        self.retired.pop(path, None)
        self.retired[path] = (ring, self.net.tick)
        total = sum(r.rows.size for r, _ in self.retired.values())
        while total > RETIRED_FLOATS:
            oldest = next(iter(self.retired))
            total -= self.retired.pop(oldest)[0].rows.size

    def use_network(self, net) -> None:
        """Record another network's buffers: every ring is dropped (server thread)."""
        self.net = net
        self.rings = {}
        self.retired = {}
        self._split = ((), ())

    def hook(self) -> None:
        """The tick hook (kernel thread): one row per ring; event rings always, the others
        in turns until the budget is spent."""
        always, others = self._split
        if not (always or others):
            return
        perf = time.perf_counter
        start = perf()
        tick = self.net.tick
        for ring in always:
            self._record(ring, tick)
        n = len(others)
        for k in range(n):
            i = (self._start + k) % n
            self._record(others[i], tick)
            if perf() - start > self.budget and k + 1 < n:
                self.skipped += n - k - 1
                self._start = (i + 1) % n
                return

    @staticmethod
    def _record(ring: Ring, tick: int) -> None:
        try:
            ring.record(tick)
        except Exception:                   # a hook must never raise into the kernel
            pass

    def read(self, since: dict[str, int]) -> dict[str, tuple[np.ndarray, np.ndarray, tuple]]:
        """(ticks, rows, shape) of every ring after the tick given for its path (kernel
        thread, between ticks)."""
        out = {}
        for path, ring in self.rings.items():
            ticks, rows = ring.since(since.get(path, -1))
            out[path] = (ticks, rows, tuple(ring.src.shape))
        return out


def envelope(ticks: np.ndarray, rows: np.ndarray, points: int
             ) -> tuple[np.ndarray, np.ndarray]:
    """Min and max of the rows in ``points`` columns of equal tick spans: (column first
    ticks, array (columns, 2, elements)); empty columns are left out."""
    first, last = int(ticks[0]), int(ticks[-1])
    span = last - first + 1
    col = ((ticks - first) * points) // span
    starts = np.concatenate(([0], np.flatnonzero(np.diff(col)) + 1))
    lows = np.minimum.reduceat(rows, starts, axis=0)
    highs = np.maximum.reduceat(rows, starts, axis=0)
    column_ticks = first + (col[starts] * span + points - 1) // points
    return column_ticks, np.stack([lows, highs], axis=1)


def encode_history(ticks: np.ndarray, rows: np.ndarray, shape: tuple, since: int,
                   points: int) -> tuple[bytes, dict]:
    """The payload and header fields of a ``history`` buffer for a client that has seen
    everything up to tick ``since``."""
    missed = _missed(ticks, since)
    head = {"buffer_shape": list(shape), "missed": missed}
    if len(ticks) <= points:
        head.update(mode="samples", ticks=ticks.tolist(), shape=[len(ticks), *shape])
        return np.ascontiguousarray(rows, "<f4").tobytes(), head
    column_ticks, env = envelope(ticks, rows, points)
    head.update(mode="envelope", ticks=column_ticks.tolist(),
                last_tick=int(ticks[-1]), shape=[len(column_ticks), 2, *shape])
    return np.ascontiguousarray(env, "<f4").tobytes(), head


def encode_events(ticks: np.ndarray, rows: np.ndarray, shape: tuple, since: int
                  ) -> tuple[bytes, dict]:
    """Every (tick, element) above 0 since tick ``since``, as float32 pairs (tick offset
    from ``first_tick``, flat element index)."""
    which, element = np.nonzero(rows > 0)
    missed = _missed(ticks, since)
    if len(which) > MAX_EVENTS:
        missed += 1
        which, element = which[-MAX_EVENTS:], element[-MAX_EVENTS:]
    first = int(ticks[0]) if len(ticks) else since + 1
    pairs = np.empty((len(which), 2), "<f4")
    pairs[:, 0] = ticks[which] - first
    pairs[:, 1] = element
    head = {"buffer_shape": list(shape), "missed": missed, "first_tick": first,
            "last_tick": int(ticks[-1]) if len(ticks) else since, "shape": [len(which), 2]}
    return pairs.tobytes(), head


def _missed(ticks: np.ndarray, since: int) -> int:
    """Ticks after ``since`` up to the last one recorded that are not in ``ticks``."""
    if since < 0 or len(ticks) == 0:
        return 0
    return int(ticks[-1] - since - len(ticks))
