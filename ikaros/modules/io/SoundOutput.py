"""SoundOutput: plays sound files when its trigger input rises."""
import math

from ikaros.module import Input, Output, Parameter, require
from ikaros.modules.sound import _audio
from ikaros.modules.sound._player import PlayerModule


class SoundOutput(PlayerModule):
    """Plays sound i of ``sounds`` (a comma-separated list of files, relative to the model
    file's folder) when element i of TRIG (Ikaros 3's name; INPUT in Ikaros 2) rises: goes
    above 0 after being 0 or below on the previous tick (the first tick counts from 0).
    While the first element of INHIBITION is above 0, rises start nothing (sounds that play
    go on). Sounds play at once, mixed; a sound triggered while it plays starts again from
    its beginning. PLAYING is 1 for each sound that is playing; COMPLETED is 1 on the tick
    a sound has ended; ACTIVE is 1 while any sound plays; RMS is the root mean square of
    each of the two channels over one tick's worth of the sound handed to the device,
    ``lag`` milliseconds ago (the device's latency: what is heard now, to move a robot's
    mouth with), and VOLUME is scale_volume × RMS, at most 1 (this project's reading of
    Ikaros 3's RMS, VOLUME, scale_volume and lag, which its reference does not describe).
    PLAYING and COMPLETED have one element per element of TRIG, or per sound with INPUT.
    Files are read at load by soundfile (WAV, FLAC, OGG, ...; ``pip install
    'ikaros[sound]'``), converted to the first file's sample rate and to stereo, and played
    through sounddevice (PortAudio) on ``device`` (the system's default output when empty;
    ``silent`` plays nothing, in step with the model's time, for machines without a sound
    card). Unlike Ikaros 2, which ran an external program (``command``, afplay or play) for
    each sound, no program is run (a ``command`` attribute in a model file is ignored), and
    a sound can be restarted."""

    sounds = Parameter("", "the sound files, separated by commas", fixed=True)
    TRIG = Input("a rise of element i plays sound i", optional=True)
    INPUT = Input("Ikaros 2's name of TRIG", optional=True)
    INHIBITION = Input("while its first element is above 0, no sound starts", optional=True)
    PLAYING = Output("1 for each sound that is playing, else 0")
    COMPLETED = Output("1 for each sound that ended on this tick, else 0")

    def configure(self):
        require("soundfile", "soundfile", extra="sound")
        self._files = [s.strip() for s in str(self.sounds).split(",") if s.strip()]
        if not self._files:
            raise ValueError("sounds is empty: give one or more sound files, separated by "
                             "commas")

    def set_sizes(self):
        shape = self.input_shape("TRIG") if self.connected("TRIG") else (len(self._files),)
        if shape is not None:
            size = max(1, math.prod(shape))
            self.set_output_shape("PLAYING", size)
            self.set_output_shape("COMPLETED", size)

    def init(self):
        trigger = self.TRIG if self.TRIG is not None else self.INPUT
        if trigger is None:
            raise ValueError("connect TRIG (or INPUT, its Ikaros 2 name): its rises play the "
                             "sounds")
        if self.TRIG is not None and self.INPUT is not None:
            self.warning("TRIG and INPUT are both connected: only TRIG plays the sounds")
        sounds, rate = [], None
        for name in self._files:
            data, rate = _audio.read_sound(self, name, rate, 2)
            sounds.append(data)
        if trigger.size < len(sounds):
            self.warning(f"the trigger has {trigger.size} elements for {len(sounds)} sounds: "
                         f"sounds {trigger.size + 1} to {len(sounds)} never play")
        count = len(sounds)
        self.start_player(sounds, rate, trigger, lambda i: i if i < count else None)

