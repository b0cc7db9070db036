"""Tests of SoundOutput, InputSound, AudioOutput and AudioInput with sound files written by
the test. The audio streams are replaced by fakes (sounddevice cannot open a device on test machines, which
have no PortAudio library and no sound card): the fake output stream is asked for blocks of
the mix by the test, the fake microphone gets blocks from the test."""
import numpy as np
import pytest
import soundfile

from ikaros.errors import ModelError
from ikaros.modules.sound import _audio
from ikaros.testing import load_body as load

RATE = 8000


class FakeStream:
    """Stands in for sounddevice's OutputStream and InputStream."""

    def __init__(self, samplerate, channels, dtype, callback, device=None):
        assert dtype == "float32"
        self.samplerate, self.channels, self.device = samplerate, channels, device
        self._callback = callback
        self.started = self.closed = False
        STREAMS.append(self)

    def start(self):
        self.started = True

    def callback(self, data):
        """What the audio thread does with each block."""
        self._callback(data, len(data), None, None)

    def pull(self, frames):
        out = np.full((frames, self.channels), np.nan, np.float32)     # all must be written
        self.callback(out)
        return out

    def close(self):
        self.closed = True


STREAMS = []


@pytest.fixture
def streams(monkeypatch):
    STREAMS.clear()
    fake = type("sounddevice", (), {"OutputStream": FakeStream, "InputStream": FakeStream})
    monkeypatch.setattr(_audio, "_sounddevice", lambda: fake)
    return STREAMS


def write(path, data, rate=RATE):
    soundfile.write(str(path), np.asarray(data, np.float32), rate, subtype="FLOAT")


def test_a_rise_plays_a_sound_and_playing_says_so(tmp_path, streams):
    write(tmp_path / "a.wav", np.full(100, 0.25))                        # mono
    write(tmp_path / "b.wav", np.column_stack([np.full(50, 0.5), np.full(50, -0.5)]))
    (tmp_path / "in.txt").write_text("T/2\n0 0\n1 0\n1 1\n1 1\n0 1\n1 1\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="in.txt"/>'
                         '<module class="SoundOutput" name="S" sounds="a.wav, b.wav" '
                         'device="3"/>'
                         '<connection source="F.T" target="S.INPUT" delay="0"/>')
    try:
        stream = streams[0]
        assert (stream.samplerate, stream.channels, stream.device) == (RATE, 2, 3)
        assert stream.started
        net.step()
        assert net.output("S.PLAYING").tolist() == [0, 0]
        assert not stream.pull(10).any()
        net.step()                                                       # a rises
        assert net.output("S.PLAYING").tolist() == [1, 0]
        assert stream.pull(60).tolist() == [[0.25, 0.25]] * 60
        net.step()                                                       # b rises
        assert net.output("S.PLAYING").tolist() == [1, 1]
        mix = stream.pull(60)
        assert mix[:40].tolist() == [[0.75, -0.25]] * 40                 # both
        assert mix[40:50].tolist() == [[0.5, -0.5]] * 10                 # a has ended
        assert not mix[50:].any()
        net.step()                                                       # held: no rise
        assert net.output("S.PLAYING").tolist() == [0, 0]
        net.step()
        net.step()                                                       # a rises again
        assert net.output("S.PLAYING").tolist() == [1, 0]
    finally:
        net.close()
    assert stream.closed


def test_files_of_another_rate_are_resampled_to_the_first(tmp_path, streams):
    write(tmp_path / "a.wav", np.zeros(10))
    write(tmp_path / "b.wav", np.linspace(0, 0.9, 10), rate=RATE // 2)
    net = load(tmp_path, '<module class="Constant" name="C" data="0 1"/>'
                         '<module class="SoundOutput" name="S" sounds="a.wav,b.wav"/>'
                         '<connection source="C.OUTPUT" target="S.INPUT"/>')
    try:
        net.run(ticks=2)
        out = streams[0].pull(20)[:, 0]
        assert np.allclose(out[:19], np.arange(19) * 0.05, atol=1e-6)   # interpolated
    finally:
        net.close()


def test_sound_output_errors(tmp_path, streams):
    with pytest.raises(ModelError, match="sounds is empty"):
        load(tmp_path, '<module class="Constant" name="C" data="1"/>'
                       '<module class="SoundOutput" name="S"/>'
                       '<connection source="C.OUTPUT" target="S.INPUT"/>')
    with pytest.raises(ModelError, match='cannot read the sound file "missing.wav"'):
        load(tmp_path, '<module class="Constant" name="C" data="1"/>'
                       '<module class="SoundOutput" name="S" sounds="missing.wav"/>'
                       '<connection source="C.OUTPUT" target="S.INPUT"/>')


@pytest.mark.parametrize("module, message", [
    ('<module class="Constant" name="C" data="1"/><module class="SoundOutput" name="S" '
     'sounds="a.wav" device="3"/><connection source="C.OUTPUT" target="S.INPUT"/>',
     "cannot open the sound output: PortAudio library not found .*libportaudio2"),
    ('<module class="InputSound" name="M" device="3"/>',
     "cannot open the microphone: PortAudio library not found .*libportaudio2")],
    ids=["output", "microphone"])
def test_no_audio_device_is_a_clear_load_error(tmp_path, monkeypatch, module, message):
    devices = []

    def no_portaudio(**settings):
        devices.append(settings["device"])
        raise OSError("PortAudio library not found")
    fake = type("sounddevice", (), {"OutputStream": staticmethod(no_portaudio),
                                    "InputStream": staticmethod(no_portaudio)})
    monkeypatch.setattr(_audio, "_sounddevice", lambda: fake)
    write(tmp_path / "a.wav", np.zeros(10))
    with pytest.raises(ModelError, match=message):
        load(tmp_path, module)
    assert devices == [3]                       # a number names the device by its index


def test_a_file_is_read_block_by_block_with_a_level(tmp_path):
    samples = np.arange(10, dtype=np.float32) / 10
    write(tmp_path / "s.wav", np.column_stack([samples, -samples]))
    net = load(tmp_path, '<module class="InputSound" name="I" filename="s.wav" samples="4" '
                         'channels="2"/>')
    try:
        assert net.output("I.OUTPUT").shape == (4, 2)
        blocks, levels = [], []
        while not net.stopped:
            net.step()
            blocks.append(net.output("I.OUTPUT")[:, 0].tolist())
            levels.append(net.output("I.LEVEL").tolist())
        expected = [samples[0:4], samples[4:8], np.r_[samples[8:10], 0, 0]]
        assert np.allclose(blocks[:3], expected)
        assert blocks[3] == [0, 0, 0, 0]                      # the end of the file
        rms = np.sqrt(np.mean(np.square(expected[1])))
        assert np.allclose(levels[1], [rms, rms])
        assert net.tick == 4
    finally:
        net.close()


def test_a_file_loops_and_is_mixed_down(tmp_path):
    write(tmp_path / "s.wav", np.column_stack([np.r_[1, 2, 3], np.r_[3, 4, 5]]) / 10)
    net = load(tmp_path, '<module class="InputSound" name="I" filename="s.wav" samples="4" '
                         'loop="yes"/>')
    try:
        net.run(ticks=2)
        assert np.allclose(net.output("I.OUTPUT").ravel(), [0.3, 0.4, 0.2, 0.3])
        assert not net.stopped
    finally:
        net.close()


def test_the_microphone_gives_the_newest_samples(tmp_path, streams):
    net = load(tmp_path, '<module class="InputSound" name="I" samples="4" '
                         'samplerate="16000"/>')
    try:
        mic = streams[0]
        assert (mic.samplerate, mic.channels) == (16000, 1)
        mic.callback(np.float32([[0.1], [0.2], [0.3]]))
        net.step()
        assert np.allclose(net.output("I.OUTPUT").ravel(), [0, 0.1, 0.2, 0.3])
        mic.callback(np.float32([[0.4], [0.5]]))
        mic.callback(np.float32([[0.6], [0.7], [0.8]]))
        net.step()
        assert np.allclose(net.output("I.OUTPUT").ravel(), [0.5, 0.6, 0.7, 0.8])
        assert np.allclose(net.output("I.LEVEL"), np.sqrt(np.mean(np.square(
            [0.5, 0.6, 0.7, 0.8]))))
        net.step()                                          # nothing new: kept
        assert np.allclose(net.output("I.OUTPUT").ravel(), [0.5, 0.6, 0.7, 0.8])
    finally:
        net.close()
    assert mic.closed


def v3_sounds(tmp_path, trig_rows, attrs="", inhibition_rows=None):
    """An Ikaros 3 SoundOutput on the silent device, its TRIG (and INHIBITION) from files;
    the sound a.wav is 100 frames of 0.5, b.wav 40 frames of 0.25 left and 0.75 right; a
    tick of 10 ms at 8000 Hz is 80 frames."""
    write(tmp_path / "a.wav", np.full(100, 0.5))
    write(tmp_path / "b.wav", np.column_stack([np.full(40, 0.25), np.full(40, 0.75)]))
    (tmp_path / "t.txt").write_text("T/2\n" + "\n".join(trig_rows) + "\n")
    body = ('<module class="InputFile" name="T" filename="t.txt"/>'
            f'<module class="SoundOutput" name="S" sounds="a.wav,b.wav" device="silent" '
            f'{attrs}/>'
            '<connection source="T.T" target="S.TRIG" delay="0"/>')
    if inhibition_rows is not None:
        (tmp_path / "i.txt").write_text("I/1\n" + "\n".join(inhibition_rows) + "\n")
        body += ('<module class="InputFile" name="I" filename="i.txt"/>'
                 '<connection source="I.I" target="S.INHIBITION" delay="0"/>')
    return load(tmp_path, body, tick_duration="0.01", dialect="3")


def outputs(net):
    return {name: net.output(f"S.{name}").tolist()
            for name in ("PLAYING", "COMPLETED", "ACTIVE", "RMS", "VOLUME")}


def test_ikaros_3_interface_completed_active_and_the_level_heard(tmp_path, monkeypatch):
    monkeypatch.setattr(_audio, "_sounddevice", lambda: pytest.fail("no sound device"))
    net = v3_sounds(tmp_path, ["1 0", "1 1", "0 0", "0 0"], 'lag="0" scale_volume="3"')
    try:
        got = []
        for _ in range(4):
            net.step()
            got.append(outputs(net))
    finally:
        net.close()
    # tick 1: a plays its first 80 frames; tick 2: its last 20, and b's 40 (mixed)
    assert got[0] == {"PLAYING": [1, 0], "COMPLETED": [0, 0], "ACTIVE": [1],
                      "RMS": [0.5, 0.5], "VOLUME": [1, 1]}
    left = np.sqrt((20 * 0.75 ** 2 + 20 * 0.25 ** 2) / 80)
    right = np.sqrt((20 * 1.0 + 20 * 0.75 ** 2) / 80)          # 0.5 + 0.75 is clipped to 1
    assert got[1]["PLAYING"] == [0, 0] and got[1]["COMPLETED"] == [1, 1]
    assert got[1]["ACTIVE"] == [0]
    assert np.allclose(got[1]["RMS"], [left, right])
    assert np.allclose(got[1]["VOLUME"], [min(1, 3 * left), min(1, 3 * right)])
    assert got[2] == {"PLAYING": [0, 0], "COMPLETED": [0, 0], "ACTIVE": [0],
                      "RMS": [0, 0], "VOLUME": [0, 0]}


def test_the_lag_delays_the_level(tmp_path):
    net = v3_sounds(tmp_path, ["1 0", "0 0", "0 0"], 'lag="10"')       # 80 frames
    try:
        levels = []
        for _ in range(3):
            net.step()
            levels.append(net.output("S.RMS").tolist())
    finally:
        net.close()
    assert levels[0] == [0, 0]
    assert levels[1] == [0.5, 0.5]
    assert np.allclose(levels[2], [np.sqrt(20 * 0.25 / 80)] * 2)


def test_inhibition_stops_sounds_from_starting(tmp_path):
    net = v3_sounds(tmp_path, ["1 0", "0 1", "0 0", "0 1"], "", ["0", "1", "0", "0"])
    try:
        playing, completed = [], []
        for _ in range(4):
            net.step()
            playing.append(net.output("S.PLAYING").tolist())
            completed.append(net.output("S.COMPLETED").tolist())
    finally:
        net.close()
    # b's first rise was inhibited; its second plays, all 40 frames within tick 4
    assert playing == [[1, 0], [0, 0], [0, 0], [0, 0]]
    assert completed == [[0, 0], [1, 0], [0, 0], [0, 1]]


def test_playing_has_one_element_per_trigger(tmp_path):
    write(tmp_path / "a.wav", np.zeros(10))
    net = load(tmp_path, '<module class="Constant" name="C" data="0 0 1"/>'
                         '<module class="SoundOutput" name="S" sounds="a.wav" device="silent"/>'
                         '<connection source="C.OUTPUT" target="S.TRIG"/>')
    try:
        assert net.output("S.PLAYING").shape == (3,)
        net.step()
        assert net.output("S.PLAYING").tolist() == [0, 0, 0]    # trigger 3 has no sound
    finally:
        net.close()


def test_a_trigger_is_needed(tmp_path):
    write(tmp_path / "a.wav", np.zeros(10))
    with pytest.raises(ModelError, match="connect TRIG .or INPUT, its Ikaros 2 name"):
        load(tmp_path, '<module class="SoundOutput" name="S" sounds="a.wav" device="silent"/>')


def test_audio_output_queues_each_block_for_the_device(tmp_path, streams):
    (tmp_path / "in.txt").write_text("V/4\n1 2 3 4\n5 6 7 8\n")
    net = load(tmp_path, '<module class="InputFile" name="I" filename="in.txt"/>'
                         '<module class="AudioOutput" name="A" sample_rate="8000" '
                         'device="2"/>'
                         '<connection source="I.V" target="A.INPUT" delay="0"/>')
    try:
        stream = streams[0]
        assert (stream.samplerate, stream.channels, stream.device, stream.started) == \
            (8000, 1, 2, True)
        assert stream.pull(3).ravel().tolist() == [0, 0, 0]         # nothing yet: silence
        net.step()
        net.step()
        assert stream.pull(5).ravel().tolist() == [1, 2, 3, 4, 5]
        assert stream.pull(5).ravel().tolist() == [6, 7, 8, 0, 0]
    finally:
        net.close()
    assert stream.closed


def test_audio_output_plays_channels_and_buffer_size(tmp_path, streams):
    (tmp_path / "in.txt").write_text("V/6\n1 2 3 4 5 6\n")
    net = load(tmp_path, '<module class="InputFile" name="I" filename="in.txt"/>'
                         '<module class="AudioOutput" name="A" buffer_size="2"/>'
                         '<connection source="I.V[0:3]" target="A.INPUT[0][]" delay="0"/>'
                         '<connection source="I.V[3:6]" target="A.INPUT[1][]" delay="0"/>',
               dialect="3")
    try:
        net.step()
        assert streams[0].channels == 2
        assert streams[0].pull(3).tolist() == [[1, 4], [2, 5], [0, 0]]
    finally:
        net.close()


def test_a_batch_run_keeps_at_most_a_second_of_sound_waiting(tmp_path, streams):
    net = load(tmp_path, '<module class="Constant" name="C" data="0.5 0.5 0.5 0.5"/>'
                         '<module class="AudioOutput" name="A" sample_rate="10"/>'
                         '<connection source="C.OUTPUT" target="A.INPUT"/>')
    try:
        net.run(ticks=5)                                     # 20 samples for 10 a second
        assert any("faster than the device plays it" in e[3] for e in net.log)
        assert streams[0].pull(12).ravel().tolist() == [0.5] * 10 + [0, 0]
    finally:
        net.close()


def test_audio_input_gives_the_newest_samples(tmp_path, streams):
    net = load(tmp_path, '<module class="AudioInput" name="M" samplingrate="16000" '
                         'buffersize="4"/>')
    try:
        mic = streams[0]
        assert (mic.samplerate, mic.channels) == (16000, 1)
        assert net.output("M.OUTPUT").shape == (4,)
        mic.callback(np.float32([[0.1], [0.2], [0.3]]))
        net.step()
        assert np.allclose(net.output("M.OUTPUT"), [0, 0.1, 0.2, 0.3])
        mic.callback(np.float32([[0.4], [0.5], [0.6], [0.7], [0.8]]))
        net.step()
        assert np.allclose(net.output("M.OUTPUT"), [0.5, 0.6, 0.7, 0.8])
        net.step()                                           # nothing new: kept
        assert np.allclose(net.output("M.OUTPUT"), [0.5, 0.6, 0.7, 0.8])
    finally:
        net.close()
    assert mic.closed


def test_no_portaudio_is_a_clear_load_error_for_the_microphone(tmp_path, monkeypatch):
    def no_portaudio(**settings):
        raise OSError("PortAudio library not found")
    fake = type("sounddevice", (), {"OutputStream": staticmethod(no_portaudio),
                                    "InputStream": staticmethod(no_portaudio)})
    monkeypatch.setattr(_audio, "_sounddevice", lambda: fake)
    with pytest.raises(ModelError, match='cannot open the microphone: PortAudio library not '
                                         'found .*libportaudio2.*device="silent"'):
        load(tmp_path, '<module class="AudioInput" name="M"/>')
