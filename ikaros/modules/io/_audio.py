"""Sound for the audio modules: reading files, a mixer of playing sounds, and the audio
streams (sounddevice), which tests replace through ``open_output_stream`` and
``open_input_stream``."""
from __future__ import annotations

import threading

import numpy as np

from ikaros.module import require


def read_sound(path: str, samplerate: int | None, channels: int) -> tuple[np.ndarray, int]:
    """A sound file as float32 (frames, channels), converted to ``channels`` (mono is
    repeated, more channels are averaged) and, when ``samplerate`` is given, resampled to it
    by linear interpolation. Returns (samples, sample rate)."""
    soundfile = require("soundfile", "soundfile", extra="sound")
    data, rate = soundfile.read(path, dtype="float32", always_2d=True)
    if data.shape[1] != channels:
        data = np.repeat(data.mean(axis=1, keepdims=True), channels, axis=1)
    if samplerate and rate != samplerate and len(data):
        n = max(1, round(len(data) * samplerate / rate))
        t = np.arange(n) * (rate / samplerate)
        data = np.stack([np.interp(t, np.arange(len(data)), c) for c in data.T],
                        axis=1).astype(np.float32)
        rate = samplerate
    return data, rate


class Mixer:
    """Sounds that play at once, summed (and clipped to -1..1) in an output callback."""

    def __init__(self, sounds: list[np.ndarray], channels: int):
        self.sounds = sounds
        self.channels = channels
        self.position = [len(s) for s in sounds]         # at the end: not playing
        self.lock = threading.Lock()

    def start(self, k: int) -> None:
        """Play sound k from its start (again, if it is playing)."""
        with self.lock:
            self.position[k] = 0

    def playing(self) -> list[bool]:
        with self.lock:
            return [p < len(s) for p, s in zip(self.position, self.sounds)]

    def fill(self, out: np.ndarray) -> None:
        """Write the next len(out) frames of the mix into ``out`` (frames, channels)."""
        out.fill(0)
        frames = len(out)
        with self.lock:
            for k, sound in enumerate(self.sounds):
                p = self.position[k]
                n = min(frames, len(sound) - p)
                if n > 0:
                    out[:n] += sound[p:p + n]
                    self.position[k] = p + n
        np.clip(out, -1, 1, out=out)


def _sounddevice():
    return require("sounddevice", "sounddevice", extra="sound")


def open_output_stream(samplerate: int, channels: int, fill, device=None):
    """A started output stream that asks ``fill(out)`` for each block of frames; it has
    ``close()``. Needs sounddevice (and the PortAudio library)."""
    sd = _sounddevice()

    def callback(outdata, frames, time, status):
        fill(outdata)
    stream = sd.OutputStream(samplerate=samplerate, channels=channels, dtype="float32",
                             callback=callback, device=device or None)
    stream.start()
    return stream


def open_input_stream(samplerate: int, channels: int, take, device=None):
    """A started input stream that passes each block of frames (frames, channels) to
    ``take``; it has ``close()``."""
    sd = _sounddevice()

    def callback(indata, frames, time, status):
        take(indata)
    stream = sd.InputStream(samplerate=samplerate, channels=channels, dtype="float32",
                            callback=callback, device=device or None)
    stream.start()
    return stream
