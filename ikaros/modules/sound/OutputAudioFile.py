"""OutputAudioFile: writes the blocks of samples it receives to a sound file."""
import os

import numpy as np

from ikaros.module import Input, Module, Parameter, require
from ikaros.modules.io._files import build_error, resolve

_SUBTYPES = {8: ("PCM_U8", "PCM_S8"), 16: ("PCM_16",), 24: ("PCM_24",), 32: ("PCM_32",)}


class OutputAudioFile(Module):
    """Writes the sound it receives to a file (Ikaros 3's class): each tick INPUT's block
    of samples is added to the file, a one-dimensional INPUT as one channel, a (channels,
    samples) INPUT (the layout of Ikaros 3's InputAudioFile) as that many channels. The
    format follows the file's extension (.wav, .aiff, .flac, .ogg and the others libsndfile
    writes, through soundfile: ``pip install 'ikaros[sound]'``), with ``bits_per_sample``
    8, 16, 24 or 32 bit integer samples; values outside -1..1 are clipped, with a warning
    once (NaN is written as 0). ``sample_rate`` 0 (the default) writes the rate at which
    samples arrive: INPUT's samples per tick / tick_duration. ``filename`` is relative to
    the model file's folder (or to the user-data folder given with ``ikaros -u``); an
    existing file is replaced. The file is opened when the model starts and closed,
    complete, when the run ends."""

    filename = Parameter("output.wav", "the sound file to write", fixed=True)
    sample_rate = Parameter(0.0, "samples per second written in the file; 0: INPUT's "
                            "samples per tick / tick_duration", range=(0, None), fixed=True)
    bits_per_sample = Parameter(16, "8, 16, 24 or 32 bit samples", type="int", fixed=True)
    INPUT = Input("a block of samples: one-dimensional (one channel) or (channels, "
                  "samples)")

    def configure(self):
        self._soundfile = require("soundfile", "soundfile", extra="sound")
        if self.bits_per_sample not in _SUBTYPES:
            raise build_error(self, f"bits_per_sample is {self.bits_per_sample}: it must be "
                              f"8, 16, 24 or 32")
        extension = os.path.splitext(self.filename)[1].lstrip(".").upper()
        self._format = {"AIF": "AIFF"}.get(extension, extension)
        if self._format not in self._soundfile.available_formats():
            raise build_error(self, f'cannot tell the sound format of "{self.filename}": '
                              f'use .wav, .aiff, .flac or another extension libsndfile '
                              f'writes')
        fits = [s for s in _SUBTYPES[self.bits_per_sample]
                if self._soundfile.check_format(self._format, s)]
        if not fits:
            raise build_error(self, f"{self._format} files cannot hold "
                              f"{self.bits_per_sample}-bit samples")
        self._subtype = fits[0]

    def init(self):
        x = self.INPUT
        self._channels = 1 if x.ndim < 2 else x.shape[0]
        frames = x.size // self._channels
        rate = self.sample_rate or frames / self.clock.tick_duration
        if rate != round(rate) or rate < 1:
            raise ValueError(f"the sample rate {rate:g} is not a whole number of samples "
                             f"per second: set sample_rate")
        self._warned = False
        path = resolve(self, self.filename, write=True)
        try:
            self._file = self._soundfile.SoundFile(path, "w", int(round(rate)),
                                                   self._channels, self._subtype,
                                                   format=self._format)
        except (RuntimeError, OSError) as e:
            raise ValueError(f'cannot write the sound file "{path}": {e}') from None

    def tick(self):
        block = np.nan_to_num(self.INPUT.reshape(self._channels, -1).T, nan=0.0)
        if not self._warned and (block.min(initial=0) < -1 or block.max(initial=0) > 1):
            self._warned = True
            self.warning("some samples are outside -1..1 and are clipped (this warning is "
                         "given once)")
        self._file.write(np.clip(block, -1, 1))

    def stop(self):
        file = getattr(self, "_file", None)
        if file is not None:
            file.close()
            self._file = None
