"""Sound for the audio modules: reading files, a mixer of playing sounds, and the audio
streams (sounddevice, which tests replace through ``_sounddevice``), including the silent
device that plays and records nothing in step with the model's time."""
from __future__ import annotations

import collections
import threading

import numpy as np

from ikaros.module import require
from ikaros.modules.io._files import resolve

# The device name of a sound device that plays nothing and records silence, in step with the
# model's time (each tick is tick_duration of sound): for machines without a sound card, for
# tests and for examples.
SILENT = "silent"
_PORTAUDIO = (f"sounddevice needs the PortAudio library: apt-get install libportaudio2 on "
              f'Debian; device="{SILENT}" runs without a sound device')


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
    return convert(data, rate, samplerate, channels)


def convert(data: np.ndarray, rate: int, samplerate: int | None,
            channels: int) -> tuple[np.ndarray, int]:
    """Samples (frames, channels) converted to ``channels`` and, when ``samplerate`` is
    given, resampled to it by linear interpolation; returns (samples, rate)."""
    if data.shape[1] != channels:
        data = np.repeat(data.mean(axis=1, keepdims=True), channels, axis=1)
    if samplerate and rate != samplerate and len(data):
        n = max(1, round(len(data) * samplerate / rate))
        t = np.arange(n) * (rate / samplerate)
        data = np.stack([np.interp(t, np.arange(len(data)), c) for c in data.T],
                        axis=1).astype(np.float32)
        rate = samplerate
    return np.ascontiguousarray(data, np.float32), rate


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
    try:
        return require("sounddevice", "sounddevice", extra="sound")
    except OSError as e:            # sounddevice is installed but PortAudio is not
        raise ValueError(f"cannot use a sound device: {e} ({_PORTAUDIO})") from None


def require_device(device: str) -> None:
    """Fail now (at build time) when a sound device is named and sounddevice is missing;
    the silent device needs nothing."""
    if not is_silent(device):
        _sounddevice()


class DeviceStream:
    """A started sounddevice stream; ``advance`` does nothing (the device keeps its own
    time)."""

    def __init__(self, stream):
        self.stream = stream

    def advance(self, seconds: float) -> None:
        pass

    def close(self) -> None:
        self.stream.close()


class SilentStream:
    """The silent device: each ``advance(seconds)`` hands that much sound, at the stream's
    rate, to ``handle``: an output stream's ``fill`` (the frames it writes are dropped) or
    an input stream's ``take`` (which gets zeros). Fractions of a frame carry over."""

    def __init__(self, samplerate: int, channels: int, handle):
        self.samplerate, self.channels, self.handle = samplerate, channels, handle
        self._owed = 0.0

    def advance(self, seconds: float) -> None:
        self._owed += seconds * self.samplerate
        frames = int(self._owed + 1e-9)
        self._owed -= frames
        if frames > 0:
            self.handle(np.zeros((frames, self.channels), np.float32))

    def close(self) -> None:
        pass


def open_output_stream(samplerate: int, channels: int, fill, device: str = ""):
    """A started output stream that asks ``fill(out)`` for each block of frames; it has
    ``advance(seconds)`` (call it every tick: the silent device plays in the model's time)
    and ``close()``. ``device``: sounddevice's name or number of the output, empty (or
    "default") for the default, "silent" for none. Needs sounddevice (and PortAudio)."""
    if is_silent(device):
        return SilentStream(samplerate, channels, fill)
    return _open_stream(_sounddevice().OutputStream, samplerate, channels, fill, device,
                        "the sound output")


def open_input_stream(samplerate: int, channels: int, take, device: str = ""):
    """A started input stream that passes each block of frames (frames, channels) to
    ``take``; it has ``advance(seconds)`` and ``close()`` (see open_output_stream)."""
    if is_silent(device):
        return SilentStream(samplerate, channels, take)
    return _open_stream(_sounddevice().InputStream, samplerate, channels, take, device,
                        "the microphone")


def is_silent(device) -> bool:
    """Whether a device parameter names the silent device."""
    return str(device).strip().lower() == SILENT


def _open_stream(stream_class, samplerate: int, channels: int, handle, device: str,
                 what: str):
    def callback(data, frames, time, status):
        handle(data)
    device = str(device).strip()
    device = None if device.lower() in ("", "default") else \
        int(device) if device.isdigit() else device
    try:
        stream = stream_class(samplerate=samplerate, channels=channels, dtype="float32",
                              callback=callback, device=device)
        stream.start()
    except OSError as e:            # no PortAudio, no device
        raise ValueError(f"cannot open {what}: {e} ({_PORTAUDIO})") from None
    return DeviceStream(stream)


def frames(x: np.ndarray, channels: int, count: int) -> np.ndarray:
    """A block of samples, one-dimensional or (channels, samples), as ``count`` frames
    (frames, channels): the first ``count`` samples of each channel, padded with zeros."""
    samples = x.reshape(channels, -1)[:, :count].T
    if len(samples) == count:
        return samples
    block = np.zeros((count, channels), np.float32)
    block[:len(samples)] = samples
    return block


class Microphone:
    """Sound from an input stream: the blocks that arrive between ticks are kept (at most
    ``keep`` frames of them) until a tick takes the newest into its output."""

    def __init__(self, samplerate: int, channels: int, keep: int, device: str = ""):
        self.keep = keep
        self._blocks: collections.deque = collections.deque()
        self._frames = 0
        self._lock = threading.Lock()
        self.stream = open_input_stream(samplerate, channels, self._take, device)

    def _take(self, block: np.ndarray) -> None:
        """Called by the audio stream's thread with each block of frames."""
        with self._lock:
            self._blocks.append(block.copy())
            self._frames += len(block)
            while self._frames - len(self._blocks[0]) >= self.keep:
                self._frames -= len(self._blocks.popleft())

    def newest_into(self, out: np.ndarray, seconds: float) -> None:
        """Let ``seconds`` of sound arrive (the silent device), then shift the frames that
        came since the last call into the end of ``out`` (frames, channels), the newest
        last; with none, ``out`` is kept."""
        self.stream.advance(seconds)
        with self._lock:
            blocks, self._blocks, self._frames = list(self._blocks), collections.deque(), 0
        if not blocks:
            return
        new = np.concatenate(blocks)[-len(out):]
        out[:len(out) - len(new)] = out[len(new):].copy()
        out[len(out) - len(new):] = new

    def close(self) -> None:
        self.stream.close()


class SampleQueue:
    """Frames waiting for an output stream: the model pushes a block every tick, the stream
    takes what it needs; at most ``capacity`` frames wait (the oldest are dropped)."""

    def __init__(self, channels: int, capacity: int):
        self.capacity = capacity
        self._blocks: collections.deque = collections.deque()
        self._frames = 0
        self._lock = threading.Lock()
        self.dropped = 0            # frames dropped because the queue was full
        self.missing = 0            # frames the stream wanted when none were waiting

    def push(self, block: np.ndarray) -> None:
        with self._lock:
            self._blocks.append(np.array(block, np.float32))
            self._frames += len(block)
            while self._frames > self.capacity:
                extra = self._frames - self.capacity
                first = self._blocks[0]
                if len(first) <= extra:
                    self._blocks.popleft()
                    cut = len(first)
                else:
                    self._blocks[0], cut = first[extra:], extra
                self._frames -= cut
                self.dropped += cut

    def fill(self, out: np.ndarray) -> None:
        """Write the waiting frames into ``out`` (frames, channels), zeros where none
        wait (called by the stream's thread)."""
        filled = 0
        with self._lock:
            while filled < len(out) and self._blocks:
                first = self._blocks[0]
                n = min(len(first), len(out) - filled)
                out[filled:filled + n] = first[:n]
                filled += n
                if n == len(first):
                    self._blocks.popleft()
                else:
                    self._blocks[0] = first[n:]
            self._frames -= filled
            self.missing += len(out) - filled
        out[filled:] = 0
