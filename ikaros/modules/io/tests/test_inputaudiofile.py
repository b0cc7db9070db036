"""Tests of InputAudioFile with WAV and AIFF files written by the tests."""
import numpy as np
import pytest
import soundfile

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

RATE = 8000


def stereo(frames: int) -> np.ndarray:
    """Left k/64, right -k/64 for sample k: exact in float32 and in 16-bit PCM."""
    k = np.arange(frames, dtype=np.float32)
    return np.column_stack([k / 64, -k / 64])


def audio(tmp_path, attrs: str):
    return load(tmp_path, f'<module class="InputAudioFile" name="A" {attrs}/>', dialect="2")


def blocks(net, ticks: int) -> list:
    out = []
    for _ in range(ticks):
        net.step()
        out.append((net.output("A.OUTPUT")[:, 0] * 64).tolist())
    return out


def test_wav_blocks_follow_each_other_and_the_last_is_padded(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(10), RATE, subtype="FLOAT")
    net = audio(tmp_path, 'filename="s.wav" block_size="4"')
    try:
        assert net.output("A.OUTPUT").shape == (4, 2)
        got, ends, times = [], [], []
        while not net.stopped:
            net.step()
            got.append(net.output("A.OUTPUT").copy())
            ends.append(float(net.output("A.END")[0]))
            times.append(float(net.output("A.TIME")[0]))
        assert [g[:, 0].tolist() for g in got] == [[0, 1 / 64, 2 / 64, 3 / 64],
                                                   [4 / 64, 5 / 64, 6 / 64, 7 / 64],
                                                   [8 / 64, 9 / 64, 0, 0], [0, 0, 0, 0]]
        assert np.array_equal(got[1][:, 1], -got[1][:, 0])
        assert ends == [0, 0, 1, 1]
        assert times == [0, np.float32(4 / RATE), np.float32(8 / RATE), np.float32(12 / RATE)]
        assert net.tick == 4                         # the run ended after the empty block
        assert any("end of the sound file" in entry[3] for entry in net.log)
    finally:
        net.close()


def test_aiff_overlapping_blocks_wrap_round(tmp_path):
    soundfile.write(tmp_path / "s.aiff", stereo(10), RATE, subtype="PCM_16")
    net = audio(tmp_path, 'filename="s.aiff" block_size="4" step="3" at_end="wrap" '
                          'channels="2"')
    try:
        assert blocks(net, 5) == [[0, 1, 2, 3], [3, 4, 5, 6], [6, 7, 8, 9], [9, 0, 1, 2],
                                  [2, 3, 4, 5]]
        assert net.output("A.END").tolist() == [0]
        assert not net.stopped
        net.step()                                    # 5..8
        net.step()                                    # 8, 9, 0, 1 wraps
        assert net.output("A.END").tolist() == [1]
    finally:
        net.close()


def test_a_block_longer_than_the_file_wraps_several_times(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(3), RATE, subtype="FLOAT")
    net = audio(tmp_path, 'filename="s.wav" block_size="7" at_end="wrap"')
    try:
        assert blocks(net, 2) == [[0, 1, 2, 0, 1, 2, 0], [1, 2, 0, 1, 2, 0, 1]]
    finally:
        net.close()


def test_without_end_of_file_the_output_stays_zero(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(5), RATE, subtype="FLOAT")
    net = audio(tmp_path, 'filename="s.wav" block_size="4" send_end_of_file="no"')
    try:
        assert blocks(net, 4) == [[0, 1, 2, 3], [4, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]
        assert not net.stopped
    finally:
        net.close()


def test_another_sample_rate_is_resampled(tmp_path):
    mono = (np.arange(8, dtype=np.float32) / 8).reshape(-1, 1)
    soundfile.write(tmp_path / "m.wav", mono, 4000, subtype="FLOAT")
    net = audio(tmp_path, 'filename="m.wav" block_size="16" sample_rate="8000"')
    try:
        net.step()
        expected = np.interp(np.arange(16) * 0.5, np.arange(8), mono[:, 0])
        assert np.allclose(net.output("A.OUTPUT")[:, 0], expected, atol=1e-7)
        net.step()
        assert net.output("A.TIME").tolist() == [np.float32(16 / 8000)]
    finally:
        net.close()


def test_a_channel_count_other_than_the_files_is_an_error(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(4), RATE, subtype="FLOAT")
    with pytest.raises(ModelError, match='the sound file "s.wav" has 2 channels but '
                                         'channels="1"') as e:
        audio(tmp_path, 'filename="s.wav" channels="1"')
    assert "model.ikg:2" in str(e.value)


@pytest.mark.parametrize("attrs, message", [
    ('filename="none.wav"', 'cannot read the sound file "none.wav"'),
    ('', "InputAudioFile needs a filename"),
    ('filename="s.wav" block_size="0"', "block_size"),
    ('filename="s.wav" at_end="loop"', '"loop" is not one of'),
])
def test_bad_parameters_are_load_errors(tmp_path, attrs, message):
    soundfile.write(tmp_path / "s.wav", stereo(4), RATE, subtype="FLOAT")
    with pytest.raises(ModelError, match=message):
        audio(tmp_path, attrs)


def test_the_file_and_block_size_are_fixed_while_running(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(4), RATE, subtype="FLOAT")
    net = audio(tmp_path, 'filename="s.wav" block_size="2"')
    try:
        with pytest.raises(ValueError, match='"A.block_size" is fixed while the model runs'):
            net.set_parameter("A.block_size", 3)
        assert net.parameter("A.block_size") == 2
        net.set_parameter("A.step", 1)              # not fixed
        assert blocks(net, 2) == [[0, 1], [1, 2]]
    finally:
        net.close()


def audio3(tmp_path, attrs: str):
    return load(tmp_path, f'<module class="InputAudioFile" name="A" {attrs}/>', dialect="3")


def test_ikaros_3_layout_is_channels_by_buffer_size_and_repeats(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(6), RATE, subtype="FLOAT")
    net = audio3(tmp_path, 'filename="s.wav" buffer_size="4" channels="2"')
    try:
        assert net.output("A.OUTPUT").shape == (2, 4)
        rows = []
        for _ in range(3):
            net.step()
            rows.append((net.output("A.OUTPUT") * 64).tolist())
        assert rows == [[[0, 1, 2, 3], [0, -1, -2, -3]],
                        [[4, 5, 0, 1], [-4, -5, 0, -1]],          # repeat: wraps
                        [[2, 3, 4, 5], [-2, -3, -4, -5]]]
        assert not net.stopped
    finally:
        net.close()


def test_ikaros_3_without_repeat_pads_and_goes_on(tmp_path):
    soundfile.write(tmp_path / "m.aiff", stereo(5)[:, :1], RATE, subtype="PCM_16")
    net = audio3(tmp_path, 'filename="m.aiff" buffer_size="4" repeat="false"')
    try:
        rows = []
        for _ in range(4):
            net.step()
            rows.append((net.output("A.OUTPUT") * 64).tolist())
        assert rows == [[[0, 1, 2, 3]], [[4, 0, 0, 0]], [[0, 0, 0, 0]], [[0, 0, 0, 0]]]
        assert not net.stopped                    # no end-of-file in an Ikaros 3 file
    finally:
        net.close()


def test_ikaros_3_defaults(tmp_path):
    soundfile.write(tmp_path / "inputaudio.wav", stereo(5000)[:, :1], RATE, subtype="FLOAT")
    net = audio3(tmp_path, "")
    try:
        assert net.output("A.OUTPUT").shape == (1, 4096)
    finally:
        net.close()
    soundfile.write(tmp_path / "inputaudio.wav", stereo(10), RATE, subtype="FLOAT")
    with pytest.raises(ModelError, match='has 2 channels but channels="1"'):
        audio3(tmp_path, "")                       # Ikaros 3: a channel mismatch fails


def test_buffer_size_wins_over_block_size_in_ikaros_2_files(tmp_path):
    soundfile.write(tmp_path / "s.wav", stereo(10), RATE, subtype="FLOAT")
    net = audio(tmp_path, 'filename="s.wav" block_size="4" buffer_size="3" repeat="yes"')
    try:
        assert net.output("A.OUTPUT").shape == (3, 2)
        assert blocks(net, 4) == [[0, 1, 2], [3, 4, 5], [6, 7, 8], [9, 0, 1]]
    finally:
        net.close()
