"""EpiVoice: plays voice sounds, chosen by intensity and varied, when its trigger rises."""
import os

import numpy as np

from ikaros.module import Input, Output, Parameter, require
from ikaros.modules.io._files import resolve

from . import _audio
from ._player import PlayerModule


class EpiVoice(PlayerModule):
    """Voice sounds for the Epi robot (Ikaros 3's class, written here from its interface:
    how the files are named and chosen is this project's reading). Element i of ``sounds``
    (names separated by commas, relative to the model file's folder) is the voice sound
    that a rise of element i of TRIG plays (unless the first element of INHIBITION is above
    0). Each sound has ``intentities`` levels of intensity (Ikaros 3's spelling) and up to
    ``variants`` recordings at each level, in files named after the sound with the level
    and the variant, both counted from 1: sounds="laugh.wav" is laugh_1_1.wav,
    laugh_1_2.wav, ... laugh_3_5.wav. INTENSITY (element i for sound i, or its first
    element; 0..1) chooses the level, min(levels, floor(INTENSITY·levels) + 1) (the first
    level when INTENSITY is not connected), and the recordings of a level are played in
    turn, so the same one never plays twice running. Every level needs at least one
    recording; missing variants are left out. The sounds are played and reported as
    SoundOutput plays its sounds: PLAYING and COMPLETED per element of TRIG, ACTIVE, and
    RMS and VOLUME of what is heard ``lag`` ms after it was handed to ``device``
    (``silent``: no sound device, in step with the model's time)."""

    sounds = Parameter("", "the voice sounds, one per element of TRIG, separated by commas",
                       fixed=True)
    intentities = Parameter(3, "the levels of intensity of each sound (Ikaros 3's spelling)",
                            type="int", range=(1, None), fixed=True)
    variants = Parameter(5, "the most recordings of each sound at each level", type="int",
                         range=(1, None), fixed=True)
    TRIG = Input("a rise of element i plays sound i")
    INTENSITY = Input("the intensity of each sound, 0..1", optional=True)
    INHIBITION = Input("while its first element is above 0, no sound starts", optional=True)
    PLAYING = Output("1 for each sound that is playing", size_set="TRIG")
    COMPLETED = Output("1 for each sound that ended on this tick", size_set="TRIG")

    def configure(self):
        require("soundfile", "soundfile", extra="sound")
        _audio.require_device(self.device)
        names = [s.strip() for s in str(self.sounds).split(",") if s.strip()]
        if not names:
            raise ValueError("sounds is empty: give one or more voice sounds, separated by "
                             "commas")
        self._files = [[self._recordings(name, level) for level in
                        range(1, self.intentities + 1)] for name in names]

    def _recordings(self, name: str, level: int) -> list[str]:
        stem, extension = os.path.splitext(name)
        files = [f"{stem}_{level}_{variant}{extension}"
                 for variant in range(1, self.variants + 1)]
        found = [f for f in files if os.path.exists(resolve(self, f))]
        if not found:
            raise ValueError(f'no recording of "{name}" at intensity {level}: '
                             f'{files[0]} to {files[-1]} are missing')
        return found

    def init(self):
        sounds, rate, self._index = [], None, []
        for levels in self._files:
            self._index.append([])
            for files in levels:
                self._index[-1].append(list(range(len(sounds), len(sounds) + len(files))))
                for name in files:
                    data, rate = _audio.read_sound(self, name, rate, 2)
                    sounds.append(data)
        self._turn = [[0] * len(levels) for levels in self._files]
        self.start_player(sounds, rate, self.TRIG, self._choose_recording)

    def _choose_recording(self, i: int) -> int | None:
        """The sound that a rise of TRIG element i plays: its level's recordings in turn."""
        if i >= len(self._index):
            return None
        levels = self._index[i]
        intensity = 0.0
        if self.INTENSITY is not None and self.INTENSITY.size:
            flat = self.INTENSITY.reshape(-1)
            intensity = float(np.clip(flat[i] if i < flat.size else flat[0], 0, 1))
        level = min(len(levels), int(np.floor(intensity * len(levels))) + 1) - 1
        recordings = levels[level]
        turn = self._turn[i][level]
        self._turn[i][level] = (turn + 1) % len(recordings)
        return recordings[turn]
