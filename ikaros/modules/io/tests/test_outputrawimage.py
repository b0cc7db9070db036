"""Tests of the OutputRawImage module."""
import numpy as np

from ikaros.module import WARNING
from ikaros.testing import load_body as load


def test_scaled_rounded_clipped_bytes(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 0.5 1; -0.2 0.1 1.5"/>\n'
                         '<module class="OutputRawImage" name="O" filename="x.raw"/>\n'
                         '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=2)
        assert len([e for e in net.log if e[1] == WARNING and "clipped" in e[3]]) == 1
    finally:
        net.close()
    got = np.fromfile(tmp_path / "x.raw", dtype=np.uint8)
    values = np.float32([0, 0.5, 1, -0.2, 0.1, 1.5])
    assert got.tolist() == np.clip(np.rint(values * np.float32(255)), 0, 255).tolist()
    assert got.tolist() == [0, 128, 255, 0, 26, 255]


def test_sequence_numbering_suppress_offset_and_scale(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" outputsize="3" min="0" max="10" '
                         'step="1"/>\n'
                         '<module class="OutputRawImage" name="O" filename="i%02d.raw" '
                         'scale="10" suppress="1" offset="5"/>\n'
                         '<connection source="S.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
    finally:
        net.close()
    assert sorted(p.name for p in tmp_path.glob("*.raw")) == ["i06.raw", "i07.raw"]
    assert np.fromfile(tmp_path / "i06.raw", np.uint8).tolist() == [20, 20, 20]
    assert np.fromfile(tmp_path / "i07.raw", np.uint8).tolist() == [30, 30, 30]


def test_round_trip_with_inputrawimage(tmp_path):
    rng = np.random.default_rng(4)
    data = rng.integers(0, 256, 20).astype(np.uint8)
    data.tofile(tmp_path / "a.raw")
    net = load(tmp_path, '<module class="InputRawImage" name="I" filename="a.raw" size_x="5" '
                         'size_y="4"/>\n'
                         '<module class="OutputRawImage" name="O" filename="b.raw"/>\n'
                         '<connection source="I.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.step()
    finally:
        net.close()
    assert np.array_equal(np.fromfile(tmp_path / "b.raw", np.uint8), data)
