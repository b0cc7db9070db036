"""InputAudioFile: a sound file (WAV, AIFF, FLAC, ...) as blocks of samples, one per tick."""
import numpy as np

from ikaros.module import Module, Output, Parameter, require

from ikaros.modules.sound import _audio


class InputAudioFile(Module):
    """Reads a sound file (WAV, AIFF, FLAC, OGG and the other formats of libsndfile, through
    soundfile: ``pip install 'ikaros[sound]'``; ``filename`` is relative to the model
    file's folder) and outputs a block of ``block_size`` samples per tick: one row per
    sample, one column per channel, values -1..1. Block k starts at sample k * ``step``
    (``step`` 0 means ``block_size``: blocks that follow each other; a smaller step gives
    overlapping blocks, as for a spectrogram). At the end of the file, ``at_end`` = pad
    fills the rest of the block with 0; once a block would start past the end, OUTPUT is 0
    and the module sends end-of-file, which ends the run (unless ``send_end_of_file`` is
    no: then OUTPUT stays 0). With ``at_end`` = wrap the file is read round and round: a
    block that reaches the end continues from the start. END is 1 on a tick whose block
    holds the file's last sample (or, with pad, comes after it), and TIME is the time in
    the file of the block's first sample. ``channels`` 0 takes the file's channels; any
    other value must be the file's number of channels, or the model does not build (the
    error names the file and both counts). ``sample_rate`` 0 keeps the file's rate; another value
    resamples the file to it when the model starts (linear interpolation, as InputSound).
    The whole file is read into memory when the model starts.
    Ikaros 3's interface is accepted too: ``buffer_size`` (its name for block_size; when set
    it wins), ``repeat`` (yes: wrap), and in a file of dialect 3 its defaults (filename
    inputaudio.wav, buffer_size 4096, channels 1, repeat yes, and no end-of-file: after the
    end of a file that does not repeat, OUTPUT is 0 and the run goes on) and its layout:
    OUTPUT is (channels, buffer_size), one row per channel. InputSound reads a file too
    (mixed to any number of channels) or the microphone."""

    filename = Parameter("", "the sound file to read; relative to the model file's folder",
                         fixed=True, default_v3="inputaudio.wav")
    block_size = Parameter(1024, "samples per tick (rows of OUTPUT)", type="int",
                           range=(1, None), fixed=True)
    buffer_size = Parameter(0, "Ikaros 3's name of block_size (when not 0 it wins)",
                            type="int", range=(0, None), fixed=True, default_v3=4096)
    step = Parameter(0, "samples from the start of one block to the start of the next; 0: "
                     "block_size", type="int", range=(0, None))
    channels = Parameter(0, "the file's number of channels (columns of OUTPUT; Ikaros 3: "
                         "rows); 0: the file's own", type="int", range=(0, None), fixed=True,
                         default_v3=1)
    sample_rate = Parameter(0, "samples per second; 0: the file's own rate, otherwise the "
                            "file is resampled to it", type="int", range=(0, None),
                            fixed=True)
    at_end = Parameter("pad", "pad: fill the last block with 0, then end; wrap: continue "
                       "from the start of the file", options="pad/wrap")
    repeat = Parameter(False, "Ikaros 3: yes wraps as at_end=wrap does", default_v3=True)
    send_end_of_file = Parameter(True, "pad: end the run when the file is exhausted; with "
                                 "no, OUTPUT is 0 from then on", default_v3=False)
    OUTPUT = Output("this tick's block: one row per sample, one column per channel (Ikaros "
                    "3: one row per channel)")
    END = Output("1 when this tick's block holds the file's last sample (or, with pad, "
                 "comes after it), else 0", size="1")
    TIME = Output("the time in the file of the first sample of this tick's block, in "
                  "seconds", size="1")

    def configure(self):
        require("soundfile", "soundfile", extra="sound")
        if not self.filename:
            raise ValueError("InputAudioFile needs a filename")
        channels, self._file_rate, _ = _audio.sound_info(self, self.filename)
        if self.channels and self.channels != channels:
            raise ValueError(f'the sound file "{self.filename}" has {channels} channel'
                             f'{"s" if channels != 1 else ""} but channels="{self.channels}"'
                             f' (0 takes the file\'s own)')
        self._channels = channels
        self._length = self.buffer_size or self.block_size
        self.set_output_shape("OUTPUT", (channels, self._length) if self.dialect == "3"
                              else (self._length, channels))

    def init(self):
        self._data, self._rate = _audio.read_sound(self, self.filename, self.sample_rate,
                                                   self._channels)
        self._position = 0              # the first sample of the next block
        self._offsets = np.arange(self._length)
        self._ended = False
        # the block as (samples, channels), whichever the layout of OUTPUT
        self._block = self.OUTPUT.T if self.dialect == "3" else self.OUTPUT

    def tick(self):
        data, out, n = self._data, self._block, self._length
        frames, p = len(data), self._position
        self.TIME[0] = p / self._rate
        wrap = (self.at_end == "wrap" or self.repeat) and frames > 0
        if not wrap and p >= frames:
            out.fill(0)
            self.END[0] = 1
            if self.send_end_of_file and not self._ended:
                self._ended = True
                self.end_of_file(f'end of the sound file "{self.filename}"')
            return
        if wrap:
            out[:] = data[(self._offsets + p) % frames]
        else:
            chunk = data[p:p + n]
            out[:len(chunk)] = chunk
            out[len(chunk):] = 0
        self.END[0] = p + n >= frames
        step = self.step or n
        self._position = (p + step) % frames if wrap else p + step
