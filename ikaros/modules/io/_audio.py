"""Sound for the audio modules: reading files, a mixer of playing sounds, and the audio
streams (sounddevice, which tests replace through ``_sounddevice``)."""
from __future__ import annotations

import threading

import numpy as np

from ikaros.module import require

from ._files import resolve


def sound_info(module, name: str) -> tuple[int, int, int]:
    """(channels, sample rate, frames) of the sound file ``name`` (relative to the
    module's model file), without reading its samples; a file that cannot be read is a
    ValueError naming it."""
    soundfile = require("soundfile", "soundfile", extra="sound")
    try:
        info = soundfile.info(resolve(module, name))
    except (RuntimeError, OSError) as e:        # soundfile's errors
        raise ValueError(f'cannot read the sound file "{name}": {e}') from None
    return info.channels, info.samplerate, info.frames


def read_sound(module, name: str, samplerate: int | None,
               channels: int) -> tuple[np.ndarray, int]:
    """The sound file ``name`` (relative to the module's model file) as float32 (frames,
    channels), converted to ``channels`` (mono is repeated, more channels are averaged)
    and, when ``samplerate`` is given, resampled to it by linear interpolation. Returns
    (samples, sample rate); a file that cannot be read is a ValueError naming it."""
    soundfile = require("soundfile", "soundfile", extra="sound")
    try:
        data, rate = soundfile.read(resolve(module, name), dtype="float32", always_2d=True)
    except (RuntimeError, OSError) as e:        # soundfile's errors
        raise ValueError(f'cannot read the sound file "{name}": {e}') from None
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


def open_output_stream(samplerate: int, channels: int, fill, device: str = ""):
    """A started output stream that asks ``fill(out)`` for each block of frames; it has
    ``close()``. ``device``: sounddevice's name or number of the output, empty for the
    default. Needs sounddevice (and the PortAudio library)."""
    return _open_stream(_sounddevice().OutputStream, samplerate, channels, fill, device,
                        "the sound output")


def open_input_stream(samplerate: int, channels: int, take, device: str = ""):
    """A started input stream that passes each block of frames (frames, channels) to
    ``take``; it has ``close()``."""
    return _open_stream(_sounddevice().InputStream, samplerate, channels, take, device,
                        "the microphone")


def _open_stream(stream_class, samplerate: int, channels: int, handle, device: str,
                 what: str):
    def callback(data, frames, time, status):
        handle(data)
    device = int(device) if str(device).isdigit() else device
    try:
        stream = stream_class(samplerate=samplerate, channels=channels, dtype="float32",
                              callback=callback, device=device or None)
        stream.start()
    except OSError as e:            # no PortAudio, no device
        raise ValueError(f"cannot open {what}: {e} (sounddevice needs the PortAudio "
                         f"library: apt-get install libportaudio2 on Debian)") from None
    return stream
