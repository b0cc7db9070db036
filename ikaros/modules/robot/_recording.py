"""The record / play / save / load machinery shared by MotionRecorder and SequenceRecorder."""
from __future__ import annotations

import os

import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.io._files import numbered, resolve

STOP, RECORD, PLAY, OFF = "stop", "record", "play", "off"
MODES = [STOP, RECORD, PLAY, OFF]


class Recorder(Module):
    """Base class: subclasses say how many channels there are (``channel_count``)."""

    max_motions = Parameter(10, "number of motions that can be stored")
    current_motion = Parameter(0, "the motion that record, play, save and load use (0-based)")
    position_data_max = Parameter(1000, "most samples a motion can hold")
    mode_string = Parameter(STOP, "the mode at start", options=MODES)
    torque_on_record = Parameter("0", "torque while recording, one for all channels or one per channel "
                                 "(0: limp, to be moved by hand)", type="array")
    filename = Parameter("motion.%02d.dat", "file name of a motion; %02d is its number")
    directory = Parameter("motions", "folder of the motion files, relative to the model file")
    sample_interval = Parameter(1, "ticks between two samples while recording")
    keypoint_time = Parameter(1.0, "seconds between two keyframes added with the keypoint command")
    interpolation = Parameter("linear", "between samples: linear, or smooth (ease in and out, for keyframes)",
                              options="linear/smooth")
    smoothing = Parameter(0.0, "play-back low-pass filter constant, 0..1 (0: none)")
    loop = Parameter(False, "play the motion again when it ends")
    load_at_start = Parameter(True, "load the motion files found in directory at start")

    TRIG = Input("a rising edge of element i plays motion i", optional=True)

    COMPLETED = Output("1 on the tick motion i finishes playing", size_param="max_motions")
    TRIG_OUT = Output("1 on the tick any motion finishes playing", size="1")
    MODE = Output("the mode, one-hot: stop, record, play, off", size="4")
    TIMESTAMPS = Output("sample times of the current motion (ms)", size_param="position_data_max")
    LENGTHS = Output("number of samples of each motion", size_param="max_motions")
    STATE = Output("the mode as a number: 0 stop, 1 record, 2 play, 3 off", size="1")
    TIME = Output("seconds since recording or playing started", size="1")
    OUTPUT = Output("the recorded values while recording and off, the motion while playing, held while stopped")
    TORQUE = Output("torque enable per channel: torque_on_record while recording, 0 when off, else 1")
    ENABLE = Output("1 where OUTPUT should drive the servos (as TORQUE)")
    KEYPOINTS = Output("the samples of the current motion, one row per sample (position_data_max rows)")

    def channel_count(self) -> int:
        raise NotImplementedError

    def source(self) -> np.ndarray:
        """The values recorded this tick, ``channel_count`` of them."""
        raise NotImplementedError

    # --- build and start -------------------------------------------------------------------
    def set_sizes(self):
        n = self.channel_count()
        if n is None:
            return
        for name in ("OUTPUT", "TORQUE", "ENABLE"):
            self.set_output_shape(name, n)
        self.set_output_shape("KEYPOINTS", (int(self.position_data_max), n))

    def init(self):
        if self.max_motions < 1 or self.position_data_max < 2:
            raise ValueError("max_motions must be at least 1 and position_data_max at least 2")
        n = self.OUTPUT.size
        self._times = [np.zeros(0) for _ in range(self.max_motions)]
        self._values = [np.zeros((0, n)) for _ in range(self.max_motions)]
        self._mode = STOP
        self._elapsed = 0
        self._held = None
        self._filtered = None
        self._last_trig = np.zeros(self.max_motions)
        if self.load_at_start:
            for index in range(self.max_motions):
                if os.path.exists(self._path(index)):
                    self._load(index)
        self._set_mode(self.mode_string)
        self._show()

    def _torque_on_record(self) -> np.ndarray:
        values = np.asarray(self.torque_on_record, dtype=np.float64).reshape(-1)
        n = self.OUTPUT.size
        if values.size in (0, 1):
            return np.full(n, values[0] if values.size else 0.0)
        if values.size != n:
            raise ValueError(f"torque_on_record has {values.size} values; give one, or one per channel ({n})")
        return values

    @property
    def _motion(self) -> int:
        index = int(self.current_motion)
        if not 0 <= index < self.max_motions:
            raise ValueError(f"current_motion {index} is outside 0..{self.max_motions - 1}")
        return index

    # --- modes -----------------------------------------------------------------------------
    def _set_mode(self, mode: str) -> None:
        if mode not in MODES:
            raise ValueError(f"unknown mode '{mode}' (one of {', '.join(MODES)})")
        self._mode = mode
        self._elapsed = 0
        self._held = None
        if mode == RECORD:
            n = self.OUTPUT.size
            self._times[self._motion] = np.zeros(0)
            self._values[self._motion] = np.zeros((0, n))
        if mode == PLAY:
            self._filtered = None
            if len(self._times[self._motion]) == 0:
                self.warning(f"motion {self._motion} is empty: nothing to play")
                self._mode = STOP

    def command(self, name, x=0, y=0, value=None):
        if name in MODES:
            self._set_mode(name)
        elif name == "select":
            self.current_motion = int(value if value is not None else x)
        elif name == "keypoint":
            self._append(self._next_keypoint_time(), self.source())
        elif name == "clear":
            self._times[self._motion] = np.zeros(0)
            self._values[self._motion] = np.zeros((0, self.OUTPUT.size))
        elif name == "save":
            self._save(self._motion)
        elif name == "load":
            self._load(self._motion)
        else:
            raise ValueError(f"unknown command '{name}' (record, play, stop, off, keypoint, clear, save, "
                             "load, select)")
        self._show()

    def _next_keypoint_time(self) -> float:
        times = self._times[self._motion]
        return float(times[-1] + 1000.0 * self.keypoint_time) if len(times) else 0.0

    def _append(self, time_ms: float, values: np.ndarray) -> bool:
        index = self._motion
        if len(self._times[index]) >= self.position_data_max:
            self.warning(f"motion {index} is full ({self.position_data_max} samples)")
            return False
        self._times[index] = np.append(self._times[index], time_ms)
        self._values[index] = np.vstack([self._values[index], values.reshape(1, -1)])
        return True

    # --- ticks -----------------------------------------------------------------------------
    def tick(self):
        self.COMPLETED[...] = 0.0
        self.TRIG_OUT[0] = 0.0
        if self.TRIG is not None:
            trig = self.TRIG.reshape(-1)[:self.max_motions]
            rising = np.flatnonzero((trig > 0) & (self._last_trig[:trig.size] <= 0))
            self._last_trig[:trig.size] = trig
            if rising.size:
                self.current_motion = int(rising[0])
                self._set_mode(PLAY)
        values = self.source()
        now_ms = self._elapsed * self.clock.tick_duration * 1000.0
        ones = np.ones(self.OUTPUT.size)
        if self._mode == RECORD:
            if self._elapsed % max(1, int(self.sample_interval)) == 0 and not self._append(now_ms, values):
                self._set_mode(STOP)
            self.OUTPUT.reshape(-1)[...] = values
            torque = self._torque_on_record()
        elif self._mode == PLAY:
            self.OUTPUT.reshape(-1)[...] = self._play(now_ms, values)
            torque = ones
        elif self._mode == OFF:
            self.OUTPUT.reshape(-1)[...] = values
            torque = 0 * ones
        else:
            if self._held is None:
                self._held = values.copy()
            self.OUTPUT.reshape(-1)[...] = self._held
            torque = ones
        self.TORQUE.reshape(-1)[...] = torque
        self.ENABLE.reshape(-1)[...] = torque
        self.TIME[0] = now_ms / 1000.0
        self._elapsed += 1
        self._show()

    def _play(self, now_ms: float, start: np.ndarray) -> np.ndarray:
        index = self._motion
        times, values = self._times[index], self._values[index]
        if now_ms >= times[-1]:
            value = values[-1]
            self.COMPLETED[index] = 1.0
            self.TRIG_OUT[0] = 1.0
            if self.loop:
                self._elapsed = -1
            else:
                self._mode = STOP
                self._held = value.copy()
        else:
            k = int(np.searchsorted(times, now_ms, side="right")) - 1
            k = max(0, min(k, len(times) - 2))
            span = times[k + 1] - times[k]
            f = 0.0 if span <= 0 else (now_ms - times[k]) / span
            if self.interpolation == "smooth":
                f = f * f * (3.0 - 2.0 * f)
            value = values[k] + f * (values[k + 1] - values[k])
        if self._filtered is None:
            self._filtered = start.astype(np.float64) if np.any(start) else value.astype(np.float64)
        s = float(self.smoothing)
        self._filtered = s * self._filtered + (1.0 - s) * value
        return self._filtered

    def _show(self) -> None:
        index = self._motion
        self.MODE[...] = [float(self._mode == m) for m in MODES]
        self.STATE[0] = MODES.index(self._mode)
        for i, times in enumerate(self._times):
            self.LENGTHS[i] = len(times)
        count = len(self._times[index])
        self.KEYPOINTS[...] = 0.0
        self.TIMESTAMPS[...] = 0.0
        self.KEYPOINTS[:count] = self._values[index]
        self.TIMESTAMPS[:count] = self._times[index]

    # --- files -----------------------------------------------------------------------------
    def _path(self, index: int) -> str:
        return os.path.join(resolve(self, self.directory), numbered(self.filename, index))

    def _save(self, index: int) -> None:
        path = self._path(index)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        data = np.column_stack([self._times[index], self._values[index]])
        header = "time_ms " + " ".join(f"channel_{c}" for c in range(self.OUTPUT.size))
        np.savetxt(path, data, fmt="%.6g", header=header)
        self.print(f"saved motion {index} ({len(data)} samples) to {path}")

    def _load(self, index: int) -> None:
        path = self._path(index)
        try:
            data = np.loadtxt(path, ndmin=2)
        except (OSError, ValueError) as error:
            raise ValueError(f"cannot load motion {index} from {path}: {error}") from None
        n = self.OUTPUT.size
        if data.size and data.shape[1] != n + 1:
            raise ValueError(f"{path} has {data.shape[1] - 1} channels; this recorder has {n}")
        data = data[:int(self.position_data_max)]
        self._times[index] = data[:, 0] if data.size else np.zeros(0)
        self._values[index] = data[:, 1:] if data.size else np.zeros((0, n))

