"""AudioInput: sound from a microphone, the newest block of samples each tick."""
from ikaros.module import Module, Output, Parameter

from . import _audio


class AudioInput(Module):
    """Records from a sound device (Ikaros 3's class): every tick OUTPUT holds the newest
    ``buffersize`` samples of one channel, at ``samplingrate`` samples per second: the
    samples that arrived since the previous tick at its end, shifted in after the older
    ones (when none arrived, OUTPUT is kept). The device is sounddevice's (PortAudio):
    ``device`` names it (a name or number as sounddevice lists them; empty: the default
    input), and ``device="silent"`` records silence in step with the model's time, for
    machines without a sound card (``pip install 'ikaros[sound]'``; on Debian also
    apt-get install libportaudio2). InputSound does the same with several channels, a
    level output, and sound files."""

    samplingrate = Parameter(44100, "samples per second", type="int", range=(1, None),
                             fixed=True)
    buffersize = Parameter(4096, "samples in OUTPUT", type="int", range=(1, None),
                           fixed=True)
    device = Parameter("", "the input device: a name or number as sounddevice lists them; "
                       "empty: the default; silent: none (silence)", fixed=True)
    OUTPUT = Output("the newest buffersize samples, the newest last")

    def configure(self):
        _audio.require_device(self.device)
        self.set_output_shape("OUTPUT", self.buffersize)

    def init(self):
        self._microphone = _audio.Microphone(self.samplingrate, 1, 4 * self.buffersize,
                                             self.device)

    def tick(self):
        self._microphone.newest_into(self.OUTPUT.reshape(-1, 1), self.clock.tick_duration)

    def stop(self):
        microphone = getattr(self, "_microphone", None)
        if microphone is not None:
            microphone.close()
            self._microphone = None
