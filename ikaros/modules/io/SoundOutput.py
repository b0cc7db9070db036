"""SoundOutput: plays sound files when its input rises."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require

from ikaros.modules.sound import _audio


class SoundOutput(Module):
    """Plays sound i of ``sounds`` (a comma-separated list of files, relative to the model
    file's folder) when element i of INPUT rises: goes above 0 after being 0 or below on the
    previous tick (the first tick counts from 0). Sounds play at once, mixed; a sound
    triggered while it plays starts again from its beginning. PLAYING is 1 for each sound
    that is playing. Files are read at load by soundfile (WAV, FLAC, OGG, ...; ``pip install
    'ikaros[sound]'``), converted to the first file's sample rate and to stereo, and played
    through sounddevice (PortAudio) on ``device`` (the system's default output when empty).
    Unlike Ikaros 2, which ran an external program (``command``, afplay or play) for each
    sound, no program is run (a ``command`` attribute in a model file is ignored), and a sound
    can be restarted."""

    sounds = Parameter("", "the sound files, separated by commas")
    device = Parameter("", "the output device: a name or number as sounddevice lists them; "
                       "empty: the default output")
    INPUT = Input("a rise of element i plays sound i")
    PLAYING = Output("1 for each sound that is playing, else 0")

    def configure(self):
        require("soundfile", "soundfile", extra="sound")
        self._files = [s.strip() for s in str(self.sounds).split(",") if s.strip()]
        if not self._files:
            raise ValueError("sounds is empty: give one or more sound files, separated by "
                             "commas")
        self.set_output_shape("PLAYING", (len(self._files),))

    def init(self):
        sounds, rate = [], None
        for name in self._files:
            data, rate = _audio.read_sound(self, name, rate, 2)
            sounds.append(data)
        if self.INPUT.size < len(sounds):
            self.warning(f"INPUT has {self.INPUT.size} elements for {len(sounds)} sounds: "
                         f"sounds {self.INPUT.size + 1} to {len(sounds)} never play")
        self._mixer = _audio.Mixer(sounds, 2)
        self._last = np.zeros(min(self.INPUT.size, len(sounds)), np.float32)
        self._stream = _audio.open_output_stream(rate, 2, self._mixer.fill, self.device)

    def tick(self):
        now = self.INPUT.reshape(-1)[:len(self._last)]
        for k in np.flatnonzero((now > 0) & (self._last <= 0)):
            self._mixer.start(int(k))
        self._last[...] = now
        self.PLAYING[...] = self._mixer.playing()

    def stop(self):
        self._stream.close()
