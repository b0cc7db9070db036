"""EpiSpeech and EpiVoice on the silent sound device. The speech program is a stand-in
espeak-ng on the PATH (a script that takes eSpeak NG's -v and -w options, knows the voice
"en" only, and writes 10 frames of 0.5 per character of the text at 8000 Hz)."""
import os
import stat
import sys

import numpy as np
import pytest
import soundfile

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

FAKE_ESPEAK = f"""#!{sys.executable}
import sys
import numpy as np
import soundfile
args = sys.argv[1:]
voice = None
if "-v" in args:
    i = args.index("-v"); voice = args[i + 1]; del args[i:i + 2]
i = args.index("-w"); path = args[i + 1]; del args[i:i + 2]
with open(__file__ + ".log", "a") as log:
    log.write(repr((voice, args)) + "\\n")
if voice not in (None, "en"):
    sys.exit("no such voice: " + voice)
soundfile.write(path, np.full(10 * len(args[0]), 0.5, np.float32), 8000, subtype="FLOAT")
"""


@pytest.fixture
def espeak(tmp_path, monkeypatch):
    folder = tmp_path / "bin"
    folder.mkdir()
    program = folder / "espeak-ng"
    program.write_text(FAKE_ESPEAK)
    program.chmod(program.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("PATH", str(folder))
    return folder / "espeak-ng.log"


def speech(tmp_path, attrs, trig_rows, inhibition="0"):
    (tmp_path / "t.txt").write_text("T/2\n" + "\n".join(trig_rows) + "\n")
    return load(tmp_path, '<module class="InputFile" name="T" filename="t.txt"/>'
                          f'<module class="Constant" name="I" data="{inhibition}"/>'
                          f'<module class="EpiSpeech" name="S" device="silent" {attrs}/>'
                          '<connection source="T.T" target="S.TRIG" delay="0"/>'
                          '<connection source="I.OUTPUT" target="S.INHIBITION" delay="0"/>',
                tick_duration="0.01")


def test_phrases_are_spoken_when_triggered(tmp_path, espeak):
    # "hello there" is 110 frames, "no" 20; a tick is 80 frames
    net = speech(tmp_path, 'text="hello there,no" voice="en" lag="0"', ["1 0", "0 1", "0 0"])
    try:
        got = []
        for _ in range(3):
            net.step()
            got.append({name: net.output(f"S.{name}").tolist()
                        for name in ("PLAYING", "COMPLETED", "ACTIVE", "RMS", "VOLUME")})
    finally:
        net.close()
    assert [eval(line) for line in espeak.read_text().splitlines()] == \
        [("en", ["hello there"]), ("en", ["no"])]
    assert got[0] == {"PLAYING": [1, 0], "COMPLETED": [0, 0], "ACTIVE": [1],
                      "RMS": [0.5, 0.5], "VOLUME": [0.5, 0.5]}
    # the last 30 frames of one and the 20 of the other, mixed: 20 frames of 1, 10 of 0.5
    level = np.sqrt((20 * 1.0 + 10 * 0.25) / 80)
    assert got[1]["PLAYING"] == [0, 0] and got[1]["COMPLETED"] == [1, 1]
    assert np.allclose(got[1]["RMS"], [level, level])
    assert got[2]["ACTIVE"] == [0] and got[2]["RMS"] == [0, 0]


def test_an_unknown_voice_falls_back_to_the_default_with_a_warning(tmp_path, espeak):
    net = speech(tmp_path, "", ["1 1"])                    # Ikaros 3's macOS voice
    try:
        assert any('cannot speak with the voice "Noelle (Enhanced)"' in e[3] for e in net.log)
        net.step()
        assert net.output("S.PLAYING").tolist() == [1, 0]  # "hello there" plays on
    finally:
        net.close()
    calls = [eval(line) for line in espeak.read_text().splitlines()]
    assert calls[:2] == [("Noelle (Enhanced)", ["hello there"]), (None, ["hello there"])]


def test_inhibition_keeps_it_quiet(tmp_path, espeak):
    net = speech(tmp_path, 'voice="en"', ["1 1"], inhibition="1")
    try:
        net.step()
        assert net.output("S.ACTIVE").tolist() == [0]
    finally:
        net.close()


def test_without_a_speech_program_the_error_says_what_to_install(tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(ModelError, match="a text-to-speech program is needed: apt-get install "
                                         "espeak-ng"):
        speech(tmp_path, "", ["1 0"])


def voice_files(tmp_path, name, levels, variants, frames=lambda level, variant: 8):
    for level in range(1, levels + 1):
        for variant in range(1, variants + 1):
            data = np.full(frames(level, variant), level / 10 + variant / 100, np.float32)
            soundfile.write(tmp_path / f"{name}_{level}_{variant}.wav", data, 8000,
                            subtype="FLOAT")


def test_epivoice_chooses_the_level_by_intensity_and_plays_variants_in_turn(tmp_path):
    voice_files(tmp_path, "laugh", 3, 2)
    voice_files(tmp_path, "sigh", 3, 1)
    os.remove(tmp_path / "laugh_3_2.wav")                     # a missing variant is left out
    (tmp_path / "t.txt").write_text("T/2 N/2\n1 0 0.1 0\n0 0 0.1 0\n1 0 0.1 0\n0 0 0.1 0\n"
                                    "1 1 0.99 0.5\n0 0 0 0\n1 0 1 0\n0 0 0 0\n1 0 1 0\n")
    net = load(tmp_path, '<module class="InputFile" name="T" filename="t.txt"/>'
                         '<module class="EpiVoice" name="V" device="silent" lag="0" '
                         'sounds="laugh.wav, sigh.wav" intentities="3" variants="2"/>'
                         '<connection source="T.T" target="V.TRIG" delay="0"/>'
                         '<connection source="T.N" target="V.INTENSITY" delay="0"/>',
               tick_duration="0.001")                          # 8 frames: one whole sound
    try:
        levels = []
        for _ in range(9):
            net.step()
            levels.append(net.output("V.RMS")[0].round(4))
    finally:
        net.close()
    played = [levels[k] for k in (0, 2, 4, 6, 8)]
    # level 1 variants 1, 2; then level 3 (0.99) variant 1 with sigh level 2 (0.5); then
    # level 3 (1.0) variant 1 again: its only recording
    assert played == [np.float32(0.11), np.float32(0.12), np.float32(0.31 + 0.21),
                      np.float32(0.31), np.float32(0.31)]


def test_epivoice_needs_a_recording_at_every_level(tmp_path):
    voice_files(tmp_path, "laugh", 2, 1)
    with pytest.raises(ModelError, match='no recording of "laugh.wav" at intensity 3: '
                                         'laugh_3_1.wav to laugh_3_5.wav are missing'):
        load(tmp_path, '<module class="Constant" name="C" data="1"/>'
                       '<module class="EpiVoice" name="V" sounds="laugh.wav" device="silent"/>'
                       '<connection source="C.OUTPUT" target="V.TRIG"/>')


def test_recorded_phrases_need_no_speech_program(tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))                 # no speech program at all
    (tmp_path / "voice").mkdir()
    soundfile.write(tmp_path / "voice" / "hello_there.wav", np.full(50, 0.25, np.float32),
                    8000, subtype="FLOAT")
    soundfile.write(tmp_path / "voice" / "no.flac", np.full(30, 0.5, np.float32), 8000)
    net = speech(tmp_path, 'text="Hello there!?,No" recordings="voice" lag="0"', ["1 0"])
    try:
        net.step()
        assert net.output("S.COMPLETED").tolist() == [1, 0]
        assert np.allclose(net.output("S.RMS"), np.sqrt(50 * 0.25 ** 2 / 80))
    finally:
        net.close()
    with pytest.raises(ModelError, match="a text-to-speech program is needed"):
        speech(tmp_path, 'text="hello there,maybe" recordings="voice"', ["1 0"])
