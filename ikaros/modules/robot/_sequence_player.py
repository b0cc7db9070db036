"""Ikaros 3's SequenceRecorder, tick by tick: states, channel modes, playing with smoothing and
a speed limit, recording and simplifying, TRIG, files. See SequenceRecorder's description."""
from __future__ import annotations

import colorsys
import os

import numpy as np

from ikaros.modules.robot._sequences import (Sequence, clock_seconds, clock_text, load_sequences,
                                             save_sequences, simplify)

STATES = ["stop", "play", "record", "pause", "off"]
PLAY_MODE, RECORD_MODE, FOLLOW_MODE, OFF_MODE = 0, 1, 2, 3


def numbers(text) -> np.ndarray:
    """The numbers of a text like ``"1, 1, 0"`` (or of an array)."""
    if isinstance(text, str):
        try:
            return np.array([float(v) for v in text.replace(",", " ").replace(";", " ").split()])
        except ValueError:
            raise ValueError(f'cannot read "{text}" as numbers') from None
    return np.asarray(text, float)


def per_channel(values, n: int, fill: float) -> np.ndarray:
    """``values`` (one for all, or one per channel) as n values; missing ones ``fill``."""
    flat = np.asarray(values, float).reshape(-1)
    if flat.size == 1:
        return np.full(n, flat[0])
    out = np.full(n, fill)
    out[:min(n, flat.size)] = flat[:n]
    return out


class SequencePlayer:
    """The recorder of one SequenceRecorder module (``m``) in an Ikaros 3 file."""

    def __init__(self, m):
        self.m = m
        self.n = int(m.channels)
        self.count = int(m.max_sequences)
        self.names = [s.strip() for s in str(m.sequence_names).split(",") if s.strip()]
        self.files = [s.strip() for s in str(m.file_names).split(",") if s.strip()]
        self.sequences = [Sequence(name) for name in self.names[:self.count]]
        self.rng = np.random.default_rng(0)
        self.state = STATES[int(np.argmax(per_channel(m.state_, len(STATES), 0.0)))]
        self.head = float(m.position) or clock_seconds(m.time)
        self.current = int(m.current_sequence)
        self.last_trig = np.zeros(self.count)
        self.recorded_from = None
        self.smoothing_from = None                # (start outputs, time smoothing began)
        self.error = False
        self._load_at_start()
        m.OUTPUT[:] = per_channel(m.default_output, self.n, 0.0)
        m.COLOR[:] = self._colors()
        if self.state == "play":
            self._start_playing()

    # --- sequences and files ----------------------------------------------------------------
    def _sequence(self, index: int | None = None) -> Sequence:
        index = self.current if index is None else index
        if not 0 <= index < self.count:
            raise ValueError(f"sequence {index} is outside 0..{self.count - 1} (max_sequences)")
        while len(self.sequences) <= index:
            self.sequences.append(Sequence(f"Sequence {len(self.sequences) + 1}"))
        return self.sequences[index]

    def _path(self, name: str) -> str:
        from ikaros.modules.io._files import resolve
        return os.path.join(resolve(self.m, str(self.m.directory)), name)

    def _load_at_start(self) -> None:
        try:
            self.load()
        except FileNotFoundError:
            pass                                   # nothing saved yet

    def load(self) -> None:
        if self.files:
            loaded = [load_sequences(self._path(name))[0] for name in self.files]
        else:
            loaded = load_sequences(self._path(str(self.m.filename)))
        self.sequences = loaded[:self.count]

    def save(self) -> None:
        if self.files:
            for k, name in enumerate(self.files[:len(self.sequences)]):
                save_sequences(self._path(name), [self.sequences[k]])
        else:
            save_sequences(self._path(str(self.m.filename)), self.sequences)
        self.m.print(f"saved {len(self.sequences)} sequences to {self._path(str(self.m.filename))}")

    def _colors(self) -> np.ndarray:
        given = np.asarray(self.m.color, float)
        palette = np.array([colorsys.hsv_to_rgb(k / 8 % 1.0, 0.7, 0.9) for k in range(self.count)])
        if given.size:
            flat = given.reshape(-1)[:self.count * 3]
            palette.reshape(-1)[:flat.size] = flat
        return palette

    # --- commands ---------------------------------------------------------------------------
    def command(self, name: str, x: float, value) -> None:
        try:
            self._command(name, x, value)
            self.error = False
        except (OSError, ValueError) as error:
            self.error = True
            self.m.warning(f"{name}: {error}")

    def _command(self, name: str, x: float, value) -> None:
        number = float(value) if value not in (None, "") else float(x)
        if name in STATES:
            self.set_state(name)
        elif name == "select":
            self._sequence(int(number))
            self.current = int(number)
        elif name == "seek":
            self.head = max(0.0, number)
        elif name == "mark_start":
            self.m.mark_start = self.head if value in (None, "") and not x else number
        elif name == "mark_end":
            self.m.mark_end = self.head if value in (None, "") and not x else number
        elif name == "keyframe":
            self._record_tick(keyframe=True)
        elif name == "clear":
            self._sequence().channels = []
        elif name == "new":
            self.sequences.append(Sequence(str(value or f"Sequence {len(self.sequences) + 1}")))
            self.current = len(self.sequences) - 1
            self._sequence()
        elif name == "save":
            self.save()
        elif name == "load":
            self.load()
        else:
            raise ValueError(f"unknown command '{name}' ({', '.join(STATES)}, select, seek, mark_start, "
                             "mark_end, keyframe, clear, new, save, load)")

    def set_state(self, state: str) -> None:
        if self.state == "record" and state != "record":
            self._finish_recording()
        self.state = state
        if state == "play":
            if not any(self._sequence().has(c) for c in range(self.n)):
                self.state = "stop"
                raise ValueError(f"sequence {self.current} ('{self._sequence().name}') is empty: nothing to play")
            self._start_playing()
        elif state == "record":
            self.recorded_from = self.head
            self.recording: list[list[tuple[float, float]]] = [[] for _ in range(self.n)]

    def _start_playing(self) -> None:
        self.head = self._start() if self.head >= self._end() else self.head
        self.smoothing_from = (self.m.OUTPUT.copy(), 0.0)
        self.m.SMOOTHING_START[:] = self.m.OUTPUT

    def _start(self) -> float:
        return float(self.m.mark_start) if float(self.m.mark_end) > float(self.m.mark_start) else 0.0

    def _end(self) -> float:
        if float(self.m.mark_end) > float(self.m.mark_start):
            return float(self.m.mark_end)
        return self._sequence().end()

    # --- ticks ------------------------------------------------------------------------------
    def tick(self) -> None:
        m = self.m
        m.COMPLETED[:] = 0.0
        self._trig()
        dt = m.clock.tick_duration
        finishing = self.state == "play" and self.head >= self._end() - 1e-9
        if finishing:
            self.head = self._end()
        inputs = per_channel(m.INPUT, self.n, 0.0)
        modes = per_channel(m.channel_mode, self.n, PLAY_MODE).astype(int)
        low, high = per_channel(m.range_min, self.n, -np.inf), per_channel(m.range_max, self.n, np.inf)
        target = self._targets(low, high)
        driven = np.isfinite(target) & np.isin(modes, [PLAY_MODE, RECORD_MODE]) & (self.state == "play")
        driven |= np.isfinite(target) & (modes == PLAY_MODE) & (self.state == "record")
        out = m.OUTPUT.copy()
        out = np.where(driven, self._approach(out, target, dt), out)
        follows = (modes == FOLLOW_MODE) | (self.state == "off") | \
            ((modes == RECORD_MODE) & (self.state in ("record", "stop")))
        out = np.where(follows & ~driven, inputs, out)
        out = np.where(modes == OFF_MODE, per_channel(m.default_output, self.n, 0.0), out)
        m.OUTPUT[:] = np.clip(out, low, high)
        m.TARGET[:] = np.nan_to_num(target)
        m.ACTIVE[:] = driven
        m.CAN_PLAY[:] = [self._sequence().has(c) for c in range(self.n)]
        if self.state == "record":
            self._record_tick(inputs=inputs, modes=modes)
        if finishing:
            self._at_the_end()
        elif self.state in ("play", "record"):
            self.head += dt
        m.PLAYING[:] = 0.0
        if self.state == "play":
            m.PLAYING[self.current] = 1.0
        m.ERROR[0] = float(self.error)
        m.time, m.end_time, m.position, m.current_sequence = (clock_text(self.head), clock_text(self._end()),
                                                              self.head, self.current)

    def _trig(self) -> None:
        trig = self.m.TRIG
        if trig is None:
            return
        values = trig.reshape(-1)[:self.count]
        rising = np.flatnonzero((values > 0) & (self.last_trig[:values.size] <= 0))
        self.last_trig[:values.size] = values
        if rising.size:
            self.current, self.head = int(rising[0]), self._start()
            self.command("play", 0, None)

    def _targets(self, low: np.ndarray, high: np.ndarray) -> np.ndarray:
        sequence = self._sequence()
        linear = per_channel(numbers(self.m.interpolation), self.n, 1.0) != 0
        values = [sequence.value(c, self.head, bool(linear[c])) for c in range(self.n)]
        return np.clip(np.array([np.nan if v is None else v for v in values]), low, high)

    def _approach(self, out: np.ndarray, target: np.ndarray, dt: float) -> np.ndarray:
        """Smoothing from where playing began over smoothing_time, then at most max_speed."""
        m = self.m
        goal = target
        if self.smoothing_from is not None:
            start, elapsed = self.smoothing_from
            span = float(m.smoothing_time)
            if span > 0 and elapsed < span:
                goal = start + (target - start) * (elapsed / span)
                self.smoothing_from = (start, elapsed + dt)
            else:
                self.smoothing_from = None
        speed = per_channel(m.max_speed, self.n, 0.0) if np.asarray(m.max_speed).size else np.zeros(self.n)
        most = np.where(speed > 0, speed * dt, np.inf)
        step = np.clip(np.nan_to_num(goal) - out, -most, most)
        m.LIMITING[0] = float(np.any(np.abs(np.nan_to_num(goal) - out) > most + 1e-9))
        return out + step

    def _at_the_end(self) -> None:
        """The play head is at the end: COMPLETED pulses; stop, or begin again with loop."""
        self.m.COMPLETED[self.current] = 1.0
        if not self.m.loop:
            self.state = "stop"
            return
        if self.m.shuffle:
            playable = [k for k, s in enumerate(self.sequences) if s.end() > 0]
            self.current = int(self.rng.choice(playable))
        self.head = self._start()

    # --- recording --------------------------------------------------------------------------
    def _record_tick(self, inputs=None, modes=None, keyframe: bool = False) -> None:
        m = self.m
        inputs = per_channel(m.INPUT, self.n, 0.0) if inputs is None else inputs
        modes = per_channel(m.channel_mode, self.n, PLAY_MODE).astype(int) if modes is None else modes
        ready = per_channel(m.input_ready("INPUT"), self.n, 0.0) != 0      # no value from the source yet
        for c in np.flatnonzero((modes == RECORD_MODE) & ready):
            if keyframe:
                self._sequence().replace(int(c), self.head, self.head, [(self.head, float(inputs[c]))])
            else:
                self.recording[c].append((self.head, float(inputs[c])))

    def _finish_recording(self) -> None:
        """The recorded stretch replaces what the recorded channels held there, simplified."""
        if self.recorded_from is None:
            return
        for c, keys in enumerate(self.recording):
            if keys:
                self._sequence().replace(c, self.recorded_from, keys[-1][0],
                                         simplify(keys, float(self.m.simplify_epsilon)))
        self.recorded_from = None
