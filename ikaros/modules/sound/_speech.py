"""Text to speech through a speech program on the machine: eSpeak NG (or eSpeak) on Linux,
``say`` on macOS. The program writes a sound file, which is read with soundfile."""
from __future__ import annotations

import os
import shutil
import subprocess
import tempfile

import numpy as np

from . import _audio

# The programs tried, in order, and how each writes `text` spoken by `voice` to `path`.
ENGINES = {
    "espeak-ng": lambda voice, path, text: ["espeak-ng", *(["-v", voice] if voice else []),
                                            "-w", path, text],
    "espeak": lambda voice, path, text: ["espeak", *(["-v", voice] if voice else []),
                                         "-w", path, text],
    "say": lambda voice, path, text: ["say", *(["-v", voice] if voice else []), "-o", path,
                                      text],
}
EXTENSIONS = {"espeak-ng": ".wav", "espeak": ".wav", "say": ".aiff"}
INSTALL = ("a text-to-speech program is needed: apt-get install espeak-ng (Debian, Ubuntu), "
           "brew install espeak-ng, or macOS's own say")
TIMEOUT = 60.0              # seconds a phrase may take to synthesize


def find_engine() -> str:
    """The first speech program found on the PATH, or a ValueError saying what to install."""
    for name in ENGINES:
        if shutil.which(name):
            return name
    raise ValueError(INSTALL)


class Synthesizer:
    """Speaks phrases into sound arrays (frames, 2) at the program's rate. A voice the
    program does not know is replaced by its default voice, with ``warn`` called once."""

    def __init__(self, voice: str, warn, engine: str | None = None):
        self.engine = engine or find_engine()
        self.voice = voice
        self.warn = warn

    def speak(self, module, text: str) -> tuple[np.ndarray, int]:
        """``text`` spoken, as (samples (frames, 2), sample rate)."""
        with tempfile.TemporaryDirectory(prefix="ikaros-speech-") as folder:
            path = os.path.join(folder, "phrase" + EXTENSIONS[self.engine])
            failure = self._run(path, text, self.voice)
            if failure and self.voice:
                self.warn(f'{self.engine} cannot speak with the voice "{self.voice}" '
                          f"({failure}); its default voice is used")
                self.voice = ""
                failure = self._run(path, text, "")
            if failure:
                raise ValueError(f'{self.engine} could not speak "{text}": {failure}')
            return _audio.read_sound(module, path, None, 2)

    def _run(self, path: str, text: str, voice: str) -> str | None:
        """Run the program; None when it wrote the file, else why not."""
        command = ENGINES[self.engine](voice, path, text)
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT)
        except (OSError, subprocess.TimeoutExpired) as e:
            return str(e)
        if done.returncode != 0 or not os.path.exists(path):
            return (done.stderr or done.stdout).strip() or f"exit status {done.returncode}"
        return None
