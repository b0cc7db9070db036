"""Live data for the web UI without slowing the kernel.

``Snapshotter.hook`` runs in the kernel's thread after every tick (``Controller.tick_hooks``).
It does nothing unless the server has asked for a snapshot (some client said ``ready`` and
the previous snapshot has been taken); then it copies the subscribed buffers into arrays
allocated when the subscriptions changed, stopping when its time budget is spent (the rest
is copied after the next tick), and hands the finished snapshot to the asyncio loop with
``call_soon_threadsafe``. ``Hub`` (in the loop) encodes the snapshot for each ready client
and sends it; a slow or stalled client simply gets fewer frames. Images are encoded once per
snapshot, whatever the number of clients, and only those a ready client asks for, in a
thread of their own that runs just below a real-time tick (``priority.below_tick_thread``).
"""
from __future__ import annotations

import asyncio
import collections
import concurrent.futures
import json
import threading
import time
from typing import Callable

import numpy as np

from .. import priority
from ..module import LEVEL_NAMES
from .encoding import IMAGE_FORMATS, JPEG_QUALITY, encode_array, encode_frame
from .history import (DEFAULT_POINTS, HISTORY_FORMATS, Recorder, encode_events,
                      encode_history)

DEFAULT_BUDGET = 0.001        # seconds of copying per tick at most
DEFAULT_MAX_RATE = 15.0       # snapshots per second at most: what keeps a busy kernel within 5 %
STATUS_INTERVAL = 0.2         # seconds between status messages


def plain(value):
    """A JSON-friendly copy: arrays and NumPy numbers to Python, non-finite floats to None."""
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, (np.generic,)):
        return plain(value.item())
    if isinstance(value, float):
        return value if np.isfinite(value) else None
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    return value


def kernel_thread_alive(controller) -> bool:
    """Whether the controller's loop runs in its background thread."""
    return controller.running


def kernel_ticking(net) -> bool:
    """Whether ticks are being run now (so the tick hook will be called soon)."""
    ctrl = net.controller
    return (not net.stopped and ctrl.state in ("play", "realtime", "step")
            and kernel_thread_alive(ctrl))


def between_ticks(net, fn, *args, **kwargs):
    """Run ``fn`` in the kernel's thread between two ticks (directly when no loop runs)."""
    ctrl = net.controller
    if not kernel_thread_alive(ctrl):
        return fn(*args, **kwargs)
    return ctrl.call(fn, *args, **kwargs)


# --- the kernel side ---------------------------------------------------------------------

class Plan:
    """The union of all subscriptions: live source arrays and their snapshot copies."""

    def __init__(self, sources: dict[str, np.ndarray], version: int):
        self.version = version
        self.entries = tuple((path, src, np.empty(src.shape, dtype=np.float32))
                             for path, src in sources.items())
        self.arrays = {path: dst for path, _, dst in self.entries}


class Snapshot:
    def __init__(self, plan: Plan, tick: int, time_: float):
        self.plan, self.tick, self.time = plan, tick, time_
        self.history: dict = {}             # path -> (ticks, rows, shape) (history.py)
        self.history_since: dict = {}       # path -> the tick the rows were read after


class _Job:
    def __init__(self, plan: Plan, done: Callable[[Snapshot | None], None],
                 not_before: float):
        self.plan = plan
        self.done = done
        self.not_before = not_before
        self.next = 0


class Snapshotter:
    """Copies subscribed buffers after a tick, on request, within a time budget."""

    def __init__(self, net, budget: float = DEFAULT_BUDGET):
        self.net = net
        self.budget = budget
        self.plan = Plan({}, 0)
        self._job: _Job | None = None
        self.copies = 0               # snapshots completed (for tests and figures)
        # kernel thread, at the end: (rows by path, the tick each was read after)
        self.read_history: Callable[[], tuple[dict, dict]] | None = None

    def set_sources(self, sources: dict[str, np.ndarray]) -> None:
        """Replace the plan (in the server's thread; a job in flight keeps its own)."""
        self.plan = Plan(sources, self.plan.version + 1)

    def request(self, done: Callable[[Snapshot | None], None],
                not_before: float = 0.0) -> None:
        """Ask for one snapshot of the current plan, taken after the first tick that ends
        at ``not_before`` (a ``perf_counter`` time) or later; ``done`` is called in the
        kernel's thread with it."""
        self._job = _Job(self.plan, done, not_before)

    @property
    def pending(self) -> bool:
        return self._job is not None

    def hook(self, budget: float | None = None) -> None:
        """The tick hook (kernel thread). Cheap when nothing is requested."""
        job = self._job
        if job is None:
            return
        perf = time.perf_counter
        start = perf()
        if budget is None and start < job.not_before:
            return                          # the frame rate cap
        try:
            limit = self.budget if budget is None else budget
            entries, i, n = job.plan.entries, job.next, len(job.plan.entries)
            while i < n:
                _, src, dst = entries[i]
                np.copyto(dst, src, casting="unsafe")
                i += 1
                if perf() - start > limit:
                    break
            job.next = i
            if i < n:
                return                      # the rest after the next tick
            self._job = None
            self.copies += 1
            snap = Snapshot(job.plan, self.net.tick, float(self.net.clock.time))
            if self.read_history is not None:
                snap.history, snap.history_since = self.read_history()
        except Exception:                   # a hook must never raise into the kernel
            self._job = None
            snap = None
        try:
            job.done(snap)
        except Exception:
            pass

    def take_now(self) -> None:
        """Finish a pending snapshot at once (between ticks, when the kernel is not ticking)."""
        self.hook(budget=float("inf"))


# --- notifications -----------------------------------------------------------------------

class LogBook:
    """The kernel's notifications with sequence numbers, read from ``net.log``."""

    def __init__(self, net, keep: int = 1000):
        self.net = net
        self.messages: collections.deque = collections.deque(maxlen=keep)
        self.next_seq = 0
        self._last = None
        self._lock = threading.Lock()

    def poll(self) -> list[dict]:
        """New messages since the last poll."""
        with self._lock:
            for _ in range(10):
                try:
                    entries = list(self.net.log)
                    break
                except RuntimeError:        # appended to while copied
                    continue
            else:
                return []
            start = 0
            if self._last is not None:
                for i in range(len(entries) - 1, -1, -1):
                    if entries[i] is self._last:
                        start = i + 1
                        break
            new = entries[start:]
            if not new:
                return []
            self._last = new[-1]
            out = []
            for tick, level, module, message in new:
                m = {"seq": self.next_seq, "tick": int(tick),
                     "level": LEVEL_NAMES.get(level, str(level)), "module": module or "",
                     "message": str(message)}
                self.next_seq += 1
                self.messages.append(m)
                out.append(m)
            return out

    def since(self, seq: int) -> tuple[int, list[dict]]:
        self.poll()
        with self._lock:
            return self.next_seq, [m for m in self.messages if m["seq"] >= seq]


# --- the server side ---------------------------------------------------------------------

class Client:
    """One WebSocket connection."""

    def __init__(self, ws):
        self.ws = ws
        self.subs: list[tuple[str, str]] = []    # (path, format)
        self.version = 0                          # bumped by every subscribe
        self.ready = False
        self.last: tuple | None = None            # (tick, version) of the last frame sent
        self.frame: bytes | None = None           # the newest frame not yet sent
        self.status: str | None = None            # the newest status not yet sent
        self.texts: collections.deque = collections.deque(maxlen=256)
        self.points: dict[str, int] = {}          # history columns per path
        self.windows: dict[str, int] = {}         # the latest ticks shown, per history path
        self.seen: dict[str, int] = {}            # last tick sent per history path
        self.seen_before: dict[str, int] = {}     # the same before the newest frame
        self.wake = asyncio.Event()
        self.frames_sent = 0

    def send_text(self, message: dict) -> None:
        self.texts.append(json.dumps(message))
        self.wake.set()

    async def run_sender(self) -> None:
        """Send what is queued, newest data only, until cancelled."""
        ws = self.ws
        while True:
            await self.wake.wait()
            self.wake.clear()
            if self.status is not None:
                text, self.status = self.status, None
                await ws.send_text(text)
            while self.texts:
                await ws.send_text(self.texts.popleft())
            if self.frame is not None:
                frame, self.frame = self.frame, None
                await ws.send_bytes(frame)
                self.frames_sent += 1


class Hub:
    """The clients of one server: subscriptions, flow control, status and log messages."""

    def __init__(self, net, status: Callable[[], dict], logbook: LogBook,
                 budget: float = DEFAULT_BUDGET, max_rate: float = DEFAULT_MAX_RATE,
                 status_interval: float = STATUS_INTERVAL):
        self.net = net
        self.status = status
        self.logbook = logbook
        self.snap = Snapshotter(net, budget)
        self.history = Recorder(net, budget)
        self.snap.read_history = self._read_history
        self.min_interval = 1.0 / max_rate if max_rate and max_rate > 0 else 0.0
        self.status_interval = status_interval
        self.rgb_quality = self.gray_quality = JPEG_QUALITY    # of JPEG images
        self.clients: set[Client] = set()
        self.loop: asyncio.AbstractEventLoop | None = None
        self.in_flight = False
        self._requested_at = -1e9
        self._ticker: asyncio.Task | None = None
        self._hooked = False
        self._encoder: concurrent.futures.ThreadPoolExecutor | None = None
        self.images_encoded = 0             # (for tests and figures)

    # --- clients -------------------------------------------------------------------------
    def add(self, client: Client) -> None:
        loop = asyncio.get_running_loop()
        if loop is not self.loop:           # a new loop (tests): forget the old one's state
            self.loop = loop
            self.in_flight = False
            self._ticker = None
        if not self._hooked:
            self.net.controller.tick_hooks.append(self.history.hook)
            self.net.controller.tick_hooks.append(self.snap.hook)
            self._hooked = True
        self.clients.add(client)
        self.logbook.poll()                 # a new client gets messages from now on
        client.status = json.dumps(self._status_message())
        client.wake.set()
        if self._ticker is None or self._ticker.done():
            self._ticker = loop.create_task(self._tick_status())

    def remove(self, client: Client) -> None:
        self.clients.discard(client)
        self._update_plan()

    def subscribe(self, client: Client, subs: list[tuple[str, str]],
                  points: dict[str, int] | None = None,
                  windows: dict[str, int] | None = None) -> None:
        client.subs = subs
        client.points = dict(points or {})
        client.windows = dict(windows or {})
        client.seen = {}
        client.seen_before = {}
        client.version += 1
        client.last = None
        self._update_plan()
        self.poke()

    def use_network(self, net) -> None:
        """Serve another network (an apply, open or new): the snapshot plan and the history
        rings are made again over its buffers for the clients' subscriptions."""
        self.net = net
        self.snap.net = net
        self.snap._job = None
        self.snap.set_sources({})
        self.history.use_network(net)
        self.in_flight = False
        self._update_plan()

    def set_ready(self, client: Client) -> None:
        client.ready = True
        self.poke()

    def broadcast(self, message: dict) -> None:
        for c in list(self.clients):
            c.send_text(message)

    def _update_plan(self) -> None:
        paths: dict[str, None] = {}
        kept: dict[str, None] = {}
        events: set[str] = set()
        for c in self.clients:
            for path, fmt in c.subs:
                paths[path] = None
                if fmt in HISTORY_FORMATS:
                    kept[path] = None
                if fmt == "events":
                    events.add(path)
        rings = self.history.rings
        if list(kept) != list(rings) or any(rings[p].always != (p in events) for p in kept):
            self.history.set_sources({p: self.net.buffer_array(p) for p in kept}, events)
        if list(paths) == [e[0] for e in self.snap.plan.entries]:
            return
        self.snap.set_sources({p: self.net.buffer_array(p) for p in paths})

    # --- flow control --------------------------------------------------------------------
    def _wanting(self) -> bool:
        tick = self.net.tick
        return any(c.ready and c.subs and c.last != (tick, c.version)
                   for c in self.clients)

    def poke(self) -> None:
        """Ask the kernel for a snapshot if a ready client needs one (loop thread). The
        kernel takes it after a tick, no sooner than the frame rate cap allows."""
        if self.in_flight or self.loop is None or not self._wanting():
            return
        now = time.perf_counter()
        not_before = self._requested_at + self.min_interval
        self._requested_at = max(now, not_before)
        self.in_flight = True
        loop = self.loop

        def done(snap):                     # kernel thread
            try:
                loop.call_soon_threadsafe(self._received, snap)
            except RuntimeError:            # the loop has closed
                pass
        self.snap.request(done, not_before)
        if not kernel_ticking(self.net):
            loop.create_task(self._take_now())

    async def _take_now(self) -> None:
        try:
            await asyncio.to_thread(between_ticks, self.net, self.snap.take_now)
        except Exception:
            pass

    def _received(self, snap: Snapshot | None) -> None:
        if snap is None:
            self.in_flight = False
            return
        targets = [c for c in list(self.clients) if c.ready and c.subs
                   and all(p in snap.plan.arrays for p, _ in c.subs)
                   and c.last != (snap.tick, c.version) and self._history_covers(c, snap)]
        if any(fmt in IMAGE_FORMATS for c in targets for _, fmt in c.subs):
            self.loop.create_task(self._distribute(snap, targets))
            return
        try:                                # raw only: at once, in this loop iteration
            cache: dict = {}
            for c in targets:
                self._send_frame(c, snap, cache)
        finally:
            self.in_flight = False
        self.poke()

    async def _distribute(self, snap: Snapshot, targets: list[Client]) -> None:
        try:
            cache: dict[tuple[str, str], bytes] = {}
            for c in targets:
                for path, fmt in c.subs:
                    if fmt in IMAGE_FORMATS and (path, fmt) not in cache:
                        array = snap.plan.arrays[path]
                        quality = self.rgb_quality if array.ndim == 3 else self.gray_quality
                        cache[(path, fmt)] = await self.loop.run_in_executor(
                            self._encoding_thread(), encode_array, array, fmt, quality)
                        self.images_encoded += 1
            for c in targets:
                if c in self.clients:
                    self._send_frame(c, snap, cache)
        finally:
            self.in_flight = False
        self.poke()

    def _encoding_thread(self) -> concurrent.futures.ThreadPoolExecutor:
        """The one thread that encodes images: below a real-time tick, so that the tick
        never waits for it (its encoder may hold Python's lock) while other processes do."""
        if self._encoder is None:
            self._encoder = concurrent.futures.ThreadPoolExecutor(
                1, "ikaros-webui-images", initializer=priority.below_tick_thread)
        return self._encoder

    def close(self) -> None:
        """End the encoding thread (once the loop no longer runs)."""
        if self._encoder is not None:
            self._encoder.shutdown(wait=False)
            self._encoder = None

    @staticmethod
    def _history_covers(c: Client, snap: Snapshot) -> bool:
        """Whether the snapshot holds every history row the client lacks: one read before
        a new subscribe (which asks for the whole ring again) does not; the client then
        waits for the next one."""
        for path, fmt in c.subs:
            if fmt in HISTORY_FORMATS and path in snap.history:
                has = (c.seen_before if c.frame is not None else c.seen).get(path, -1)
                if has > snap.tick:         # a new network counts from 0 again
                    has = -1
                if snap.history_since.get(path, -1) > has:
                    return False
        return True

    def _read_history(self) -> tuple[dict, dict]:
        """The history rows every client still needs, and the tick they were read after
        per path (kernel thread, between ticks)."""
        since: dict[str, int] = {}
        for c in list(self.clients):
            for path, fmt in c.subs:
                if fmt in HISTORY_FORMATS:
                    # from before the newest frame: it may be replaced unsent (_send_frame)
                    seen = min(c.seen.get(path, -1), c.seen_before.get(path, -1)) \
                        if path in c.seen_before else -1
                    since[path] = min(since.get(path, seen), seen)
        return (self.history.read(since) if since else {}), since

    @staticmethod
    def _send_frame(c: Client, snap: Snapshot, cache: dict) -> None:
        arrays = snap.plan.arrays
        items = []
        # a frame not yet sent is replaced by this one: its history must come again
        if c.frame is not None:
            c.seen = dict(c.seen_before)
        c.seen_before = dict(c.seen)
        for path, fmt in c.subs:
            if fmt in HISTORY_FORMATS:
                items.append(Hub._history_item(c, snap, path, fmt))
                continue
            key = (path, fmt)
            if key not in cache:
                cache[key] = encode_array(arrays[path], fmt)
            items.append((path, fmt, arrays[path].shape, cache[key]))
        c.frame = encode_frame(snap.tick, snap.time, items)
        c.ready = False
        c.last = (snap.tick, c.version)
        c.wake.set()

    @staticmethod
    def _history_item(c: Client, snap: Snapshot, path: str, fmt: str) -> tuple:
        """What a client has not seen of a history buffer (history.py)."""
        since = c.seen.get(path, -1)
        if since > snap.tick:               # a new network counts from 0 again
            since = -1
        if path not in snap.history:        # no ring yet: this tick's value (below)
            arr = snap.plan.arrays[path]
            found = (np.empty(0, np.int64), np.empty((0, arr.size), np.float32),
                     tuple(arr.shape))
        else:
            found = snap.history[path]
        ticks, rows, shape = found
        keep = ticks > since
        ticks, rows = ticks[keep], rows[keep]
        if snap.tick > since and (len(ticks) == 0 or ticks[-1] < snap.tick):
            # subscribed while paused: the ring has not seen this tick, the snapshot has
            arr = snap.plan.arrays[path]
            ticks = np.append(ticks, snap.tick)
            rows = np.concatenate([rows, arr.reshape(1, -1)])
        window = c.windows.get(path)
        if window and fmt == "history" and len(ticks) and ticks[-1] - window > since:
            # only the ticks the client shows: what came before would be thrown away
            since = int(ticks[-1]) - window
            keep = ticks > since
            ticks, rows = ticks[keep], rows[keep]
        if fmt == "events":
            payload, head = encode_events(ticks, rows, shape, since)
        else:
            payload, head = encode_history(ticks, rows, shape, since,
                                           c.points.get(path, DEFAULT_POINTS))
        if len(ticks):
            c.seen[path] = int(ticks[-1])
        return (path, fmt, head.pop("shape"), payload, head)

    # --- status and log ------------------------------------------------------------------
    def _status_message(self) -> dict:
        return {"type": "status", **self.status()}

    async def _tick_status(self) -> None:
        while self.clients:
            await asyncio.sleep(self.status_interval)
            if not self.clients:
                break
            try:
                text = json.dumps(self._status_message())
                new = self.logbook.poll()
            except Exception:
                continue
            log = json.dumps({"type": "log", "messages": new}) if new else None
            for c in list(self.clients):
                c.status = text
                if log:
                    c.texts.append(log)
                c.wake.set()
            # A request made while ticking that the kernel will not take (it paused):
            if self.in_flight and self.snap.pending and not kernel_ticking(self.net):
                self.loop.create_task(self._take_now())
            self.poke()
