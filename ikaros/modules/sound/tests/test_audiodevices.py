"""AudioInput and AudioOutput on the silent device (their tests on stand-in sounddevice
streams are in ikaros/modules/io/tests/test_sound.py, with those of SoundOutput and
InputSound)."""
from ikaros.modules.sound import _audio
from ikaros.testing import load_body as load


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
