"""OutputAudioFile: the blocks it receives, read back from the file with soundfile."""
import numpy as np
import pytest
import soundfile

from ikaros.errors import ModelError
from ikaros.testing import load_body as load


def write(tmp_path, attrs, data_rows, ticks, **top):
    text = f"V/{len(data_rows[0])}\n" + "\n".join(" ".join(str(v) for v in r)
                                                  for r in data_rows)
    (tmp_path / "in.txt").write_text(text + "\n")
    body = ('<module class="InputFile" name="I" filename="in.txt"/>'
            f'<module class="OutputAudioFile" name="W" {attrs}/>'
            '<connection source="I.V" target="W.INPUT" delay="0"/>')
    net = load(tmp_path, body, **top)
    try:
        net.run(ticks=ticks)
    finally:
        net.close()


def test_mono_blocks_at_the_rate_they_arrive(tmp_path):
    rows = [[k / 8, -k / 8, 0.5, 0] for k in range(3)]
    write(tmp_path, 'filename="out.wav"', rows, 3, tick_duration="0.001")
    data, rate = soundfile.read(tmp_path / "out.wav", dtype="float32")
    info = soundfile.info(tmp_path / "out.wav")
    assert (rate, info.channels, info.subtype) == (4000, 1, "PCM_16")
    assert data.tolist() == [v for r in rows for v in r]


def test_channels_by_rows_24_bits_and_clipping(tmp_path):
    # INPUT is 2 × 3 (Ikaros 3 selectors): channel 0 is 0.25 0.5 2, channel 1 their negatives
    (tmp_path / "in.txt").write_text("V/6\n0.25 0.5 2 -0.25 -0.5 -2\n")
    body = ('<module class="InputFile" name="I" filename="in.txt"/>'
            '<module class="OutputAudioFile" name="W" filename="out.aiff" sample_rate="8000" '
            'bits_per_sample="24"/>'
            '<connection source="I.V[0:3]" target="W.INPUT[0][]" delay="0"/>'
            '<connection source="I.V[3:6]" target="W.INPUT[1][]" delay="0"/>')
    net = load(tmp_path, body, dialect="3")
    try:
        net.run(ticks=1)
        assert any("outside -1..1 and are clipped" in e[3] for e in net.log)
    finally:
        net.close()
    data, rate = soundfile.read(tmp_path / "out.aiff", dtype="float64")
    assert rate == 8000 and soundfile.info(tmp_path / "out.aiff").subtype == "PCM_24"
    assert np.allclose(data, [[0.25, -0.25], [0.5, -0.5], [1, -1]], atol=2 ** -22)


@pytest.mark.parametrize("attrs, message", [
    ('filename="x.wav" bits_per_sample="12"', "bits_per_sample is 12: it must be 8, 16, 24 "
                                              "or 32"),
    ('filename="x.mp9"', 'cannot tell the sound format of "x.mp9"'),
    ('filename="x.ogg" bits_per_sample="24"', "OGG files cannot hold 24-bit samples")])
def test_bad_parameters_are_load_errors(tmp_path, attrs, message):
    with pytest.raises(ModelError, match=message):
        write(tmp_path, attrs, [[0]], 1)
