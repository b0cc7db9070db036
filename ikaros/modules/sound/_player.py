"""Sounds started by the rises of a trigger input and mixed on one output stream, with what
Ikaros 3's SoundOutput, EpiSpeech and EpiVoice report about them: PLAYING, COMPLETED,
ACTIVE, and the RMS and VOLUME of the sound that is heard."""
from __future__ import annotations

import threading
from typing import Callable

import numpy as np

from ikaros.module import Module, Output, Parameter

from . import _audio

CHANNELS = 2                # the sounds are played in stereo


class History:
    """The last ``capacity`` frames handed to the sound device (frames, channels)."""

    def __init__(self, capacity: int, channels: int):
        self.frames = np.zeros((capacity, channels), np.float32)
        self.end = 0                    # frames handed over so far
        self.lock = threading.Lock()

    def add(self, block: np.ndarray) -> None:
        with self.lock:
            capacity = len(self.frames)
            self.end += len(block) - min(len(block), capacity)
            block = block[-capacity:]
            at = self.end % capacity
            first = min(len(block), capacity - at)
            self.frames[at:at + first] = block[:first]
            self.frames[:len(block) - first] = block[first:]
            self.end += len(block)

    def rms(self, count: int, lag: int) -> np.ndarray:
        """The root mean square of each channel over ``count`` frames that end ``lag``
        frames before the newest (frames not yet played count as 0)."""
        with self.lock:
            capacity = len(self.frames)
            stop = self.end - lag
            start = max(stop - count, self.end - capacity, 0)
            if count <= 0 or stop <= start:
                return np.zeros(self.frames.shape[1], np.float32)
            index = np.arange(start, stop) % capacity
            window = self.frames[index]
        return np.sqrt(np.sum(np.square(window, dtype=np.float64), axis=0) / count)


class TriggeredPlayer:
    """Plays sound ``choose(i)`` (an index into ``sounds``, or None for none) when element i
    of the trigger rises (goes above 0 after being 0 or below; the first tick counts from
    0), unless inhibited; a sound started while it plays starts again from its beginning.
    The sounds are (frames, 2) arrays at ``rate``, mixed on ``device`` (sounddevice's, or
    "silent": played in the model's time, each tick taking a tick's worth)."""

    def __init__(self, sounds: list[np.ndarray], rate: int, device: str, triggers: int,
                 lag_seconds: float, tick_seconds: float):
        self.rate = rate
        self.mixer = _audio.Mixer(sounds, CHANNELS)
        window = max(1, round(tick_seconds * rate))
        lag = max(0, round(lag_seconds * rate))
        self.history = History(window + lag + rate, CHANNELS)
        self.owner = [-1] * triggers            # the sound trigger i started last
        self.last = np.zeros(triggers, np.float32)
        self.was_playing = np.zeros(triggers, bool)
        self.playing = np.zeros(triggers, bool)
        self.completed = np.zeros(triggers, bool)
        self.stream = _audio.open_output_stream(rate, CHANNELS, self._fill, device)

    def _fill(self, out: np.ndarray) -> None:
        self.mixer.fill(out)
        self.history.add(out)

    def step(self, trigger: np.ndarray, inhibited: bool, choose: Callable[[int], int | None],
             seconds: float) -> None:
        """One tick: start the sounds whose trigger rose, let ``seconds`` of sound play (the
        silent device), then note which play and which have ended."""
        trigger = trigger.reshape(-1)[:len(self.last)]
        started = np.zeros(len(self.last), bool)
        rises = np.flatnonzero((trigger > 0) & (self.last[:len(trigger)] <= 0))
        self.last[:len(trigger)] = trigger
        if not inhibited:
            for i in rises.tolist():
                k = choose(i)
                if k is not None:
                    self.mixer.start(k)
                    self.owner[i] = k
                    started[i] = True
        self.stream.advance(seconds)
        sounding = self.mixer.playing()
        self.playing[:] = [k >= 0 and sounding[k] for k in self.owner]
        self.completed[:] = (self.was_playing | started) & ~self.playing
        self.was_playing[:] = self.playing

    def rms(self, seconds: float, lag_seconds: float) -> np.ndarray:
        """Each channel's root mean square over ``seconds`` of the sound handed to the
        device, ending ``lag_seconds`` before the newest (what is heard now, when the
        device's latency is the lag)."""
        return self.history.rms(round(seconds * self.rate), round(lag_seconds * self.rate))

    def close(self) -> None:
        self.stream.close()


def write_outputs(module, player: TriggeredPlayer, scale_volume: float, lag_ms: float) -> None:
    """Set a module's PLAYING, COMPLETED, ACTIVE, RMS and VOLUME: RMS over the last tick's
    worth of sound, ``lag_ms`` milliseconds ago; VOLUME is scale_volume × RMS, at most 1."""
    n = min(module.PLAYING.size, len(player.playing))
    module.PLAYING.reshape(-1)[:n] = player.playing[:n]
    module.COMPLETED.reshape(-1)[:n] = player.completed[:n]
    module.ACTIVE[...] = float(any(player.mixer.playing()))
    level = player.rms(module.clock.tick_duration, lag_ms / 1000.0)
    module.RMS[...] = level
    module.VOLUME[...] = np.minimum(1.0, scale_volume * level)


class PlayerModule(Module):
    """The base of SoundOutput, EpiSpeech and EpiVoice: a TriggeredPlayer driven by the
    module's trigger and INHIBITION, and the outputs it reports."""

    scale_volume = Parameter(1.0, "VOLUME is RMS times this, at most 1")
    lag = Parameter(100.0, "milliseconds between handing sound to the device and hearing "
                    "it: RMS and VOLUME describe the sound handed over this long ago",
                    range=(0, None))
    device = Parameter("", "the output device: a name or number as sounddevice lists them; "
                       "empty: the default output; silent: none (played in the model's "
                       "time)", fixed=True)
    ACTIVE = Output("1 while any sound plays", size="1")
    RMS = Output("the root mean square of the sound heard now, left and right", size="2")
    VOLUME = Output("scale_volume × RMS, at most 1, left and right", size="2")

    def start_player(self, sounds: list[np.ndarray], rate: int, trigger: np.ndarray,
                     choose: Callable[[int], int | None]) -> None:
        """Call in init: play ``sounds`` (frames, 2) at ``rate``, sound ``choose(i)`` when
        element i of ``trigger`` rises."""
        self._trigger, self._choose = trigger, choose
        self._player = TriggeredPlayer(sounds, rate, self.device, trigger.size,
                                       self.lag / 1000.0, self.clock.tick_duration)

    def tick(self):
        inhibition = getattr(self, "INHIBITION", None)
        inhibited = inhibition is not None and inhibition.size > 0 and inhibition.flat[0] > 0
        self._player.step(self._trigger, inhibited, self._choose, self.clock.tick_duration)
        write_outputs(self, self._player, self.scale_volume, self.lag)

    def stop(self):
        player = getattr(self, "_player", None)
        if player is not None:
            player.close()
            self._player = None
