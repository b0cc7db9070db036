"""InputSound: sound from a microphone or a file, a block of samples and a level per tick."""
import numpy as np

from ikaros.module import Module, Output, Parameter, require
from ikaros.modules.sound import _audio


class InputSound(Module):
    """Sound for models that listen: every tick OUTPUT holds the next ``samples`` samples
    (one row per sample, one column per channel, -1..1) and LEVEL the root mean square of
    each channel over them. From a file (``filename``, relative to the model file's folder;
    WAV, FLAC, OGG, ... through soundfile: ``pip install 'ikaros[sound]'``) the blocks follow
    each other; the last one is padded with 0 and then the run ends (or, with ``loop``, the
    file starts again); the file is resampled to ``samplerate`` when that is set. Without a
    filename it records from the microphone (sounddevice; ``device`` as sounddevice names
    it, empty for the default input) at ``samplerate`` (44100 when unset): each tick takes
    the samples that arrived since the previous one, the newest ``samples`` of them, padded
    in front with the previous tick's when fewer came (``device="silent"``: silence, for a
    machine without a sound card). With the default 441 samples and a
    tick of 10 ms, a tick holds 10 ms of sound at 44.1 kHz. A new class (Ikaros 2 had none
    for sound input)."""

    filename = Parameter("", "a sound file to read; empty: the microphone")
    samples = Parameter(441, "samples per tick (rows of OUTPUT)", type="int")
    channels = Parameter(1, "channels (columns of OUTPUT); a file is mixed down or repeated "
                         "to this number", type="int")
    samplerate = Parameter(0, "samples per second; 0: the file's own rate (44100 for the "
                           "microphone)", type="int")
    loop = Parameter(False, "start the file again at its end instead of ending the run")
    device = Parameter("", "the input device for the microphone (sounddevice's name or "
                       "number); empty: the default; silent: no sound device, silence")
    OUTPUT = Output("this tick's samples: one row per sample, one column per channel")
    LEVEL = Output("the root mean square of each channel over this tick's samples")

    def configure(self):
        require("soundfile", "soundfile", extra="sound")
        if self.samples < 1 or self.channels < 1 or self.samplerate < 0:
            raise ValueError(f"samples ({self.samples}) and channels ({self.channels}) must "
                             f"be 1 or more and samplerate ({self.samplerate}) 0 or more")
        self.set_output_shape("OUTPUT", (self.samples, self.channels))
        self.set_output_shape("LEVEL", (self.channels,))

    def init(self):
        self._microphone = None
        if self.filename:
            self._data, self.rate = _audio.read_sound(self, self.filename, self.samplerate,
                                                      self.channels)
            self._position = 0
            return
        self.rate = self.samplerate or 44100
        self._microphone = _audio.Microphone(self.rate, self.channels, 4 * self.samples,
                                             self.device)

    def tick(self):
        if self._microphone is None:
            self._read_file()
        else:
            self._microphone.newest_into(self.OUTPUT, self.clock.tick_duration)
        np.sqrt(np.mean(np.square(self.OUTPUT), axis=0), out=self.LEVEL)

    def _read_file(self):
        n, data, out = self.samples, self._data, self.OUTPUT
        if self._position >= len(data):
            if not self.loop or not len(data):
                out.fill(0)
                self.end_of_file(f'end of sound file "{self.filename}"')
                return
            self._position = 0
        filled = 0
        while filled < n:
            chunk = data[self._position:self._position + n - filled]
            out[filled:filled + len(chunk)] = chunk
            filled += len(chunk)
            self._position += len(chunk)
            if filled < n and not (self.loop and len(data)):
                out[filled:] = 0
                break
            if self._position >= len(data) and filled < n:
                self._position = 0

    def stop(self):
        if self._microphone is not None:
            self._microphone.close()
