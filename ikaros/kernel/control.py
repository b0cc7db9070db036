"""The control API: run modes (stop, pause, step, play, fast-forward, real time) shared by
the command line and the web UI, with requests applied between ticks."""
from __future__ import annotations

import gc
import queue
import threading
import time
from concurrent.futures import Future

from .. import priority
from ..module import PRINT, WARNING
from .timing import Waiter

STOP, PAUSE, STEP, PLAY, REALTIME = "stop", "pause", "step", "play", "realtime"
FASTFORWARD = "fastforward"
STATES = (STOP, PAUSE, STEP, PLAY, FASTFORWARD, REALTIME)
# Fast-forward is play with the tick hooks (the web UI's copies) run at most this often.
FASTFORWARD_HOOK_INTERVAL = 0.1     # seconds
COARSE_WAIT_MARGIN = 0.05           # seconds before a real-time tick left to the precise wait
DEFAULT_RESYNC_LAG = 0.1   # seconds late before real time resynchronises instead of catching up


class Controller:
    """Runs a network in one of the run modes.

    ``run`` drives the loop in the calling thread; ``start`` drives it in a background
    thread, and then ``call`` runs a function between two ticks (parameter changes,
    commands, reading outputs) from any thread.
    """

    def __init__(self, net):
        self.net = net
        self.state = PAUSE
        self.end_tick: int | None = None
        self._requests: queue.SimpleQueue = queue.SimpleQueue()
        self._wake = threading.Event()
        self._thread: threading.Thread | None = None
        self._base: tuple[float, int] | None = None
        self._waiter = Waiter()
        self._last_warning = 0.0
        # Called in the run thread after every tick (the web UI copies what its clients
        # subscribed to here); each must be quick and must not raise.
        self.tick_hooks: list = []
        self._steps = 0
        self._step_lock = threading.Lock()
        self._priority_told = False
        text = net.top.attrs.get("real_time_resync_lag")
        self.resync_lag = float(text) if text not in (None, "") else DEFAULT_RESYNC_LAG

    # --- modes ---------------------------------------------------------------------------
    def set_state(self, state: str) -> None:
        if state not in STATES:
            raise ValueError(f'unknown run mode "{state}" (one of {", ".join(STATES)})')
        if state == REALTIME and self.state != REALTIME:
            self._base = None          # time spent paused is not owed
        with self._step_lock:
            self._steps = self._steps + 1 if state == STEP else 0
        self.state = state
        self._wake.set()

    def pause(self) -> None:
        self.set_state(PAUSE)

    def step(self) -> None:
        """Run exactly one tick, then pause (steps asked for in a row each run one tick)."""
        self.set_state(STEP)

    def play(self) -> None:
        self.set_state(PLAY)

    def realtime(self) -> None:
        self.set_state(REALTIME)

    def stop(self) -> None:
        """Leave the loop after the current tick; the run can go on (``start``, ``run``)."""
        self.set_state(STOP)

    def end(self, timeout: float = 30.0) -> None:
        """Stop the loop and end the run as the end of a batch run does: the network
        closes, so every module's stop() is called once and drivers put their devices in
        the safe state at once. The network runs no more ticks after this."""
        self.stop()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            thread.join(timeout)
            if thread.is_alive():
                raise TimeoutError(f"the run did not stop within {timeout:g} s")
        self.net.close()

    # --- requests between ticks ----------------------------------------------------------
    def call(self, fn, *args, **kwargs):
        """Run ``fn`` between two ticks and return its result (directly when no loop runs
        in another thread)."""
        if self._thread is None or threading.current_thread() is self._thread:
            return fn(*args, **kwargs)
        done: Future = Future()
        self._requests.put((fn, args, kwargs, done))
        self._wake.set()
        return done.result(timeout=30)

    def _drain(self) -> None:
        if self._requests.empty():
            return
        while True:
            try:
                fn, args, kwargs, done = self._requests.get_nowait()
            except queue.Empty:
                return
            try:
                done.set_result(fn(*args, **kwargs))
            except Exception as e:
                done.set_exception(e)

    # --- the loop ------------------------------------------------------------------------
    def run(self, state: str = PLAY, ticks: int | None = None) -> int:
        """Run in this thread until ``ticks`` more ticks, the stop tick, the end of the run,
        or ``stop()``. Returns the ticks completed."""
        net = self.net
        self.end_tick = None if ticks is None else net.tick + int(ticks)
        if self.end_tick is None and net.stop_tick is not None and net.stop_tick >= 0:
            self.end_tick = net.stop_tick
        self.set_state(state)
        self._loop()
        if self.state != STOP:
            self.state = PAUSE       # the time between two runs is not owed to real time
        return net.tick

    def start(self, state: str = PAUSE) -> None:
        """Run the loop in a background thread."""
        stop = self.net.stop_tick
        self.end_tick = stop if stop is not None and stop >= 0 else None
        self.set_state(state)
        self._thread = threading.Thread(target=self._loop, name="ikaros-run", daemon=True)
        self._thread.start()

    @property
    def running(self) -> bool:
        """Whether the loop runs in its background thread."""
        return self._thread is not None and self._thread.is_alive()

    def join(self, timeout: float | None = None) -> None:
        if self._thread is not None:
            self._thread.join(timeout)

    def _loop(self) -> None:
        # Objects that live as long as the network need not be traced by every full
        # garbage collection: freezing them keeps collections short while ticks are due.
        gc.freeze()
        self._claim_priority()
        try:
            self._run_loop()
        finally:
            self.net.thread_pools.set_realtime(False)
            gc.unfreeze()

    def _claim_priority(self) -> None:
        """Give the thread that runs the ticks the priority the run asked for, and say once
        what was granted and what was refused."""
        granted = priority.tick_thread()
        if granted is None or self._priority_told:
            return
        self._priority_told = True
        cores = granted["cpus"]
        text = f"priority: tick thread {granted['tick_thread']}" \
               + (f", cores {','.join(map(str, cores))}" if cores else "") \
               + (", memory locked" if granted["memory_locked"] else "")
        self.net.notify(PRINT, None, text)
        for refusal in granted["refused"]:
            self.net.notify(WARNING, None, f"priority refused: {refusal}")

    def _run_loop(self) -> None:
        net, timing, pools = self.net, self.net.timing, self.net.thread_pools
        perf = time.perf_counter
        hooks_done, skipped = 0.0, False
        while True:
            self._drain()
            state = self.state
            if state == STOP or net.stopped:
                break
            if self.end_tick is not None and net.tick >= self.end_tick:
                if self._thread is None:
                    break
                self.state = PAUSE
                state = PAUSE
            if state == STEP:
                with self._step_lock:
                    if self._steps == 0:
                        self.state = state = PAUSE
                    else:
                        self._steps -= 1
            if state == PAUSE:
                if skipped:                 # the last fast-forwarded tick is seen
                    skipped = False
                    for hook in self.tick_hooks:
                        hook()
                self._wake.wait(0.05)
                self._wake.clear()
                continue
            if (state == REALTIME) is not pools.active:
                pools.set_realtime(state == REALTIME)
            lag = None
            now = perf()
            if state == REALTIME:
                dt = net.clock.tick_duration
                if self._base is None:
                    self._base = (now, net.tick)
                t0, n0 = self._base
                deadline = t0 + (net.tick - n0) * dt
                if deadline - now > COARSE_WAIT_MARGIN:
                    # A long wait is woken by a change of state or a request, so a stop
                    # (SIGTERM, the stop button) runs no further tick and waits for none.
                    waited = perf()
                    self._wake.wait(deadline - now - COARSE_WAIT_MARGIN)
                    self._wake.clear()
                    timing.idle += perf() - waited
                    continue
                if now < deadline:
                    timing.idle += self._waiter.wait_until(deadline)
                    now = perf()
                lag = now - deadline
                if lag > self.resync_lag:
                    self._resync(now, lag)
            timing.tick_started(now, lag)
            net.clock.lag = lag or 0.0
            net._tick()
            if state == FASTFORWARD:
                skipped = now - hooks_done < FASTFORWARD_HOOK_INTERVAL
                if skipped:
                    continue
                hooks_done = now
            for hook in self.tick_hooks:
                hook()
        self._drain()

    def _resync(self, now: float, lag: float) -> None:
        """A long stall: start the time base again instead of catching up in a burst."""
        self._base = (now, self.net.tick)
        self.net.timing.resyncs += 1
        if now - self._last_warning > 1.0:
            self._last_warning = now
            self.net.notify(WARNING, None, f"real time lagged {lag * 1000:.1f} ms at tick "
                                           f"{self.net.tick}; resynchronising the clock")

    def figures(self) -> dict:
        """State, tick and timing figures of the run."""
        net = self.net
        out = {"state": self.state, "tick": net.tick,
               "tick_duration": net.clock.tick_duration, "time": net.clock.time}
        out.update(net.timing.figures())
        out["priority"] = priority.report()
        out["thread_pools"] = net.thread_pools.report()
        return out
