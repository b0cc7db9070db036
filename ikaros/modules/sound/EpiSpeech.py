"""EpiSpeech: speaks phrases when its trigger input rises, and reports the level heard."""
import os
import re

from ikaros.module import Input, Output, Parameter
from ikaros.modules.io._files import resolve

from . import _audio
from ._player import PlayerModule
from ._speech import Synthesizer


class EpiSpeech(PlayerModule):
    """Speech for the Epi robot (Ikaros 3's class, written here from its interface): phrase
    i of ``text`` (phrases separated by commas) is spoken when element i of TRIG rises (goes
    above 0 after being 0 or below), unless the first element of INHIBITION is above 0. The
    phrases are spoken by a text-to-speech program on the machine when the model starts:
    eSpeak NG (``apt-get install espeak-ng``) or eSpeak, or ``say`` on macOS, with
    ``voice`` (Ikaros 3's default is a macOS voice; a voice the program does not know gives
    a warning and its default voice); without one the model does not start and the error
    says what to install. A phrase that has a recording in the folder ``recordings`` (a
    file named after the phrase in lower case, each run of other characters than letters
    and digits as one _: "hello_there.wav"; .wav, .aiff, .flac or .ogg) is played from it
    instead, so a robot can speak with recorded voices, and a model whose phrases all have
    recordings needs no speech program. The spoken phrases are played and reported as SoundOutput plays
    its sounds: PLAYING and COMPLETED per phrase, ACTIVE, and RMS and VOLUME of what is
    heard ``lag`` ms after it was handed to ``device`` (``silent``: no sound device, in step
    with the model's time). ATTRIBUTE1 and ATTRIBUTE2 are accepted and not used: Ikaros 3's
    reference does not say what they do."""

    voice = Parameter("Noelle (Enhanced)", "the voice of the speech program", fixed=True)
    text = Parameter("hello there,yes,no", "the phrases, separated by commas", fixed=True)
    recordings = Parameter("", "a folder of recordings of phrases, played instead of "
                           "speaking them (relative to the model file's folder)", fixed=True)
    TRIG = Input("a rise of element i speaks phrase i")
    INHIBITION = Input("while its first element is above 0, no phrase starts")
    ATTRIBUTE1 = Input("accepted, not used", optional=True)
    ATTRIBUTE2 = Input("accepted, not used", optional=True)
    PLAYING = Output("1 for each phrase that is being spoken", size_set="TRIG")
    COMPLETED = Output("1 for each phrase that ended on this tick", size_set="TRIG")

    def configure(self):
        self._phrases = [p.strip() for p in str(self.text).split(",")]
        if not any(self._phrases):
            raise ValueError("text is empty: give one or more phrases, separated by commas")
        _audio.require_device(self.device)
        self._recorded = {p: self._recording(p) for p in self._phrases}
        self._synthesizer = None
        if not all(self._recorded.values()):
            self._synthesizer = Synthesizer(self.voice, self.warning)

    def _recording(self, phrase: str) -> str | None:
        """The recording of a phrase in the recordings folder, or None."""
        if not self.recordings:
            return None
        stem = re.sub(r"[^a-z0-9]+", "_", phrase.lower()).strip("_")
        for extension in (".wav", ".aiff", ".flac", ".ogg"):
            path = resolve(self, os.path.join(self.recordings, stem + extension))
            if os.path.exists(path):
                return path
        return None

    def init(self):
        sounds, rate = [], None
        for phrase in self._phrases:
            recording = self._recorded[phrase]
            if recording is not None:
                data, phrase_rate = _audio.read_sound(self, recording, None, 2)
            else:
                data, phrase_rate = self._synthesizer.speak(self, phrase or " ")
            data, rate = _audio.convert(data, phrase_rate, rate, 2)
            sounds.append(data)
        count = len(sounds)
        self.start_player(sounds, rate, self.TRIG, lambda i: i if i < count else None)
