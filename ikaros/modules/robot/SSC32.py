"""SSC32: RC servos on a Lynxmotion SSC-32 controller."""
import threading

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SSC32(Module):
    """Drives RC servos on a Lynxmotion SSC-32 board over a serial port. Element i of INPUT is
    the position of the servo on channel ``channels[i]`` (default: channel i), from 0 to 1: its
    pulse width is min + INPUT * (max - min) µs, clipped to min..max (``min``, ``max`` and
    ``home`` give one value for all servos or one per servo). Every tick the channels whose
    position changed are sent in one group move (``#0P1500#1P900T20\\r``), taking ``move_time``
    ms (0: as fast as the servos go) at most ``speed`` µs/s per servo (0: no limit). Nothing
    moves until the model says so: nothing is sent before the first tick, nor for an element
    of INPUT that has not yet received a value from its source (``Module.input_ready``: with
    the default delays, Constant -> Scale -> SSC32 sends its first move on tick 2, not the
    zeros of the start as a move to ``min``). OUTPUT is the present
    position of each servo read back from the board (QP queries) in the same 0..1 units, NaN for
    a channel that has no pulses yet. When the run ends the servos are put in ``safe_state``:
    off (no pulses: RC servos go limp), hold (the last position is kept) or home (moved to the
    home pulse width); the same happens after ``watchdog`` seconds without a tick (paused,
    stopped, hung: the positions are sent again when ticks resume), at interpreter exit, and on
    the ``safe_state`` command. ``port="sim:ssc32"`` runs the board simulator in this process
    (see docs/robots.md). A board that does not answer, or answers with garbage, stops the run
    with an error naming the port. The Ikaros 2 class had only min, max and home; port,
    baud_rate, channels, move_time, speed, safe_state, watchdog and feedback are additions."""

    port = Parameter("/dev/ttyUSB0", "the serial device of the SSC-32, or sim:ssc32 for the "
                     "simulator")
    baud_rate = Parameter(115200, "baud rate of the board (its jumpers: 2400, 9600, 38400 "
                          "or 115200)")
    min = Parameter("500", "pulse width (µs) at position 0, one for all or one per servo",
                    type="array")
    max = Parameter("2500", "pulse width (µs) at position 1, one for all or one per servo",
                    type="array")
    home = Parameter("1500", "pulse width (µs) of the home position, one for all or one "
                     "per servo (used by safe_state=home)", type="array")
    channels = Parameter("", "the board channel of each INPUT element (default 0, 1, ...)",
                         type="array")
    move_time = Parameter(0, "duration of each move in ms (0: as fast as possible)",
                          type="int")
    speed = Parameter(0, "largest servo speed in µs per second (0: no limit)", type="int")
    safe_state = Parameter("off", "what the servos do when the run ends",
                           options="off/hold/home")
    watchdog = Parameter(1.0, "seconds without a tick before the servos are put in the safe "
                         "state (0: never)")
    feedback = Parameter(True, "read the present positions back every tick")

    INPUT = Input("servo positions, 0..1 from min to max")
    OUTPUT = Output("present servo positions read from the board, 0..1 (NaN: no pulses)",
                    shape="INPUT.shape")

    def init(self):
        from ikaros.hardware.ssc32 import CHANNELS, PULSE_MAX, PULSE_MIN, SSC32 as Board
        self._board = self._simulator = self._watchdog = self._exit_key = None
        self._lock = threading.Lock()
        n = self.INPUT.size
        self._channels = [int(c) for c in self.channels] if self.channels.size else list(range(n))
        if len(self._channels) != n:
            raise ValueError(f"channels lists {len(self._channels)} channels but INPUT has "
                             f"{n} elements")
        if any(not 0 <= c < CHANNELS for c in self._channels) or \
                len(set(self._channels)) != n:
            raise ValueError(f"channels must be different numbers in 0..{CHANNELS - 1}")
        self._min, self._max, self._home = (self._per_servo(name, n) for name in
                                            ("min", "max", "home"))
        for name, values in (("min", self._min), ("max", self._max), ("home", self._home)):
            if np.any((values < PULSE_MIN) | (values > PULSE_MAX)):
                raise ValueError(f"{name} pulse widths must be in {PULSE_MIN}..{PULSE_MAX} µs")
        self._sent = np.full(n, -1)
        self.OUTPUT.fill(np.nan)
        self._open(Board)

    def _per_servo(self, name, n):
        values = np.asarray(getattr(self, name), np.float64).reshape(-1)
        if values.size == 1:
            return np.full(n, values[0])
        if values.size != n:
            raise ValueError(f"{name} has {values.size} values; give one, or one per servo "
                             f"({n})")
        return values

    def _open(self, board_class):
        from ikaros.hardware.simulators import open_device_string
        device, self._simulator = open_device_string(self.port)
        try:
            self._board = board_class(device, int(self.baud_rate))
        except Exception:
            self.stop()
            raise
        from ikaros.hardware import safety
        self._exit_key = safety.on_exit(f"the SSC-32 at {device}", self._safe_state)
        self._watchdog = safety.Watchdog(float(self.watchdog), self._safe_state,
                                         f"{self.path}-watchdog")

    def tick(self):
        with self._lock:
            if self._watchdog.kick():                 # made safe while idle: send all again
                self._sent[...] = -1
            self._tick()

    def _tick(self):
        position = np.clip(np.nan_to_num(self.INPUT.reshape(-1), nan=0.5), 0.0, 1.0)
        pulses = np.rint(self._min + position * (self._max - self._min)).astype(int)
        ready = self.input_ready("INPUT")
        changed = {self._channels[i]: int(p) for i, p in enumerate(pulses)
                   if ready[i] and p != self._sent[i]}
        if changed:
            speeds = {c: self.speed for c in changed} if self.speed > 0 else None
            self._board.move(changed, self.move_time or None, speeds)
            self._sent = np.where(ready, pulses, self._sent)
        if self.feedback:
            present = np.asarray(self._board.pulse_widths(self._channels), np.float64)
            span = self._max - self._min
            with np.errstate(invalid="ignore", divide="ignore"):
                position = np.where(present > 0, (present - self._min) / span, np.nan)
            self.OUTPUT.reshape(-1)[...] = position

    def command(self, name, x=0, y=0, value=None):
        if self._board is None:
            return
        if name == "home":
            with self._lock:
                self._move_home()
        elif name == "safe_state":
            self._safe_state()

    def _move_home(self):
        self._board.move({c: int(h) for c, h in zip(self._channels, self._home)},
                         self.move_time or None)
        self._sent = np.rint(self._home).astype(int)

    def _safe_state(self):
        """Put the servos in safe_state (called by stop, the watchdog and at exit)."""
        with self._lock:
            if self._board is None:
                return
            if self.safe_state == "off":
                self._board.off(self._channels)
                self._sent[...] = 0
            elif self.safe_state == "home":
                self._move_home()

    def stop(self):
        from ikaros.hardware import safety
        safety.shut_down(self._watchdog, self._safe_state, self._exit_key, self._board,
                         self._simulator, lambda error: self.error(
                             f"the servos could not be put in the safe state: {error}"))
        self._board = self._simulator = None
