"""AudioInput and AudioOutput on a stand-in sound device (sounddevice replaced by fakes:
test machines have no PortAudio and no sound card) and on the silent device."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.modules.sound import _audio
from ikaros.testing import load_body as load


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
        self._callback(data, len(data), None, None)

    def pull(self, frames):
        out = np.full((frames, self.channels), 99, np.float32)
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


def test_the_silent_device_needs_no_sound_card(tmp_path, monkeypatch):
    def no_sounddevice():
        raise AssertionError("the silent device must not open sounddevice")
    monkeypatch.setattr(_audio, "_sounddevice", no_sounddevice)
    net = load(tmp_path, '<module class="AudioInput" name="M" buffersize="8" device="silent"/>'
                         '<module class="AudioOscillator" name="O" sample_rate="1000"/>'
                         '<module class="AudioOutput" name="A" device="silent" '
                         'sample_rate="1000"/>'
                         '<connection source="O.OUTPUT" target="A.INPUT"/>')
    try:
        net.run(ticks=3)
        assert net.output("M.OUTPUT").tolist() == [0] * 8
        assert not any("faster than the device" in e[3] for e in net.log)
    finally:
        net.close()


def test_the_silent_stream_hands_over_the_sound_of_each_tick():
    got = []
    stream = _audio.SilentStream(1000, 2, lambda block: got.append(block.shape))
    for _ in range(3):
        stream.advance(0.0025)                           # 2.5 frames a tick
    assert got == [(2, 2), (3, 2), (2, 2)]


def test_no_portaudio_is_a_clear_load_error(tmp_path, monkeypatch):
    def no_portaudio(**settings):
        raise OSError("PortAudio library not found")
    fake = type("sounddevice", (), {"OutputStream": staticmethod(no_portaudio),
                                    "InputStream": staticmethod(no_portaudio)})
    monkeypatch.setattr(_audio, "_sounddevice", lambda: fake)
    with pytest.raises(ModelError, match='cannot open the microphone: PortAudio library not '
                                         'found .*libportaudio2.*device="silent"'):
        load(tmp_path, '<module class="AudioInput" name="M"/>')
