"""AudioOutput: plays the blocks of samples it receives on a sound device."""
from ikaros.module import Input, Module, Parameter

from . import _audio

QUEUE_SECONDS = 1.0         # at most this much sound waits for the device


class AudioOutput(Module):
    """Plays its input on a sound device (Ikaros 3's class): each tick the first
    ``buffer_size`` frames of INPUT (0: all of it; Ikaros 3's default is sample_rate ×
    tick_duration, one tick's worth) join a queue that the device plays at ``sample_rate``:
    a one-dimensional INPUT is one channel, a (channels, samples) INPUT that many. When the
    device wants sound and none is waiting it plays silence; when the model makes sound
    faster than the device plays it (a batch run), at most one second waits and the oldest
    is dropped, with a warning once. The device is sounddevice's (PortAudio): ``device``
    names it (a name or number as sounddevice lists them; empty: the default output), and
    ``device="silent"`` plays nothing, taking the sound in step with the model's time, for
    machines without a sound card (``pip install 'ikaros[sound]'``; on Debian also
    apt-get install libportaudio2)."""

    sample_rate = Parameter(44100, "samples per second played", type="int", range=(1, None),
                            fixed=True)
    buffer_size = Parameter(0, "frames of INPUT played per tick; 0: all of INPUT (Ikaros "
                            "3: sample_rate × tick_duration)", type="int", range=(0, None),
                            fixed=True)
    device = Parameter("", "the output device: a name or number as sounddevice lists them; "
                       "empty: the default; silent: none", fixed=True)
    INPUT = Input("a block of samples: one-dimensional (one channel) or (channels, samples)")

    def configure(self):
        _audio.require_device(self.device)

    def init(self):
        x = self.INPUT
        self._channels = 1 if x.ndim < 2 else x.shape[0]
        self._frames = self.buffer_size or x.size // self._channels
        self._queue = _audio.SampleQueue(self._channels,
                                         max(2 * self._frames,
                                             round(QUEUE_SECONDS * self.sample_rate)))
        self._warned = False
        self._stream = _audio.open_output_stream(self.sample_rate, self._channels,
                                                 self._queue.fill, self.device)

    def tick(self):
        block = _audio.frames(self.INPUT, self._channels, self._frames)
        self._queue.push(block)
        self._stream.advance(self.clock.tick_duration)
        if self._queue.dropped and not self._warned:
            self._warned = True
            self.warning("the model makes sound faster than the device plays it: the oldest "
                         "waiting sound is dropped (this warning is given once)")

    def stop(self):
        stream = getattr(self, "_stream", None)
        if stream is not None:
            stream.close()
            self._stream = None
