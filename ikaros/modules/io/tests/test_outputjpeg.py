"""Tests of the OutputJPEG module."""
import numpy as np
import pytest
from PIL import Image

from ikaros.errors import ModelError
from ikaros.module import WARNING
from ikaros.testing import load_body as load


def read(path):
    with Image.open(path) as img:
        return img.mode, np.asarray(img, dtype=np.float64) / 255


def test_gray_and_colour_files_quality_100(tmp_path):
    gray = np.linspace(0, 1, 48).reshape(6, 8)
    rows = "; ".join(" ".join(f"{v:.6f}" for v in row) for row in gray)
    net = load(tmp_path,
               f'<module class="Constant" name="G" data="{rows}"/>\n'
               '<module class="Constant" name="R" data="1 1; 1 1"/>\n'
               '<module class="Constant" name="B" data="0.2 0.2; 0.2 0.2"/>\n'
               '<module class="OutputJPEG" name="OG" filename="g.jpg"/>\n'
               '<module class="OutputJPEG" name="OC" filename="c.jpg"/>\n'
               '<connection source="G.OUTPUT" target="OG.INTENSITY" delay="0"/>\n'
               '<connection source="R.OUTPUT" target="OC.RED" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="OC.BLUE" delay="0"/>')
    try:
        net.step()
    finally:
        net.close()
    mode, g = read(tmp_path / "g.jpg")
    assert mode == "L" and g.shape == (6, 8)
    assert np.abs(g - gray).max() < 0.03
    mode, c = read(tmp_path / "c.jpg")
    assert mode == "RGB" and c.shape == (2, 2, 3)
    assert np.allclose(c[..., 0], 1, atol=0.02) and np.allclose(c[..., 1], 0, atol=0.02)
    assert np.allclose(c[..., 2], 0.2, atol=0.02)            # GREEN unconnected: 0


def test_numbering_suppress_offset_and_scale(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="S" outputsize_x="4" outputsize_y="4" min="0" '
               'max="1" step="0.1"/>\n'
               '<module class="OutputJPEG" name="O" filename="f%03d.jpg" suppress="2" '
               'offset="10" scale="2"/>\n'
               '<connection source="S.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=5)
    finally:
        net.close()
    names = sorted(p.name for p in tmp_path.glob("*.jpg"))
    assert names == ["f012.jpg", "f013.jpg", "f014.jpg"]
    for number, value in ((12, 0.6), (13, 0.8), (14, 1.0)):   # 2 × (0.3, 0.4, 0.5)
        assert np.allclose(read(tmp_path / f"f{number:03d}.jpg")[1], value, atol=0.01)


def test_write_gate_single_trig_and_file_numbers(tmp_path):
    (tmp_path / "w.txt").write_text("W/1\n0\n1\n1\n0\n1\n")
    body = ('<module class="InputFile" name="W" filename="w.txt"/>\n'
            '<module class="Constant" name="C" data="0.5 0.5"/>\n'
            '<module class="OutputJPEG" name="A" filename="a%d.jpg"/>\n'
            '<module class="OutputJPEG" name="B" filename="b%d.jpg" single_trig="yes"/>\n'
            '<module class="OutputJPEG" name="N" filename="n%d.jpg" single_trig="yes" '
            'increase_file_no_on_trig="yes"/>\n')
    for name in "ABN":
        body += (f'<connection source="C.OUTPUT" target="{name}.INTENSITY" delay="0"/>\n'
                 f'<connection source="W.W" target="{name}.WRITE" delay="0"/>\n')
    net = load(tmp_path, body)
    try:
        net.run(ticks=5)
    finally:
        net.close()
    files = sorted(p.name for p in tmp_path.glob("*.jpg"))
    assert files == ["a1.jpg", "a2.jpg", "a4.jpg", "b1.jpg", "b4.jpg", "n0.jpg", "n1.jpg"]


def test_values_outside_0_1_are_clipped_with_one_warning(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="-1 0.5 2"/>\n'
                         '<module class="OutputJPEG" name="O" filename="x.jpg"/>\n'
                         '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert len([e for e in net.log if e[1] == WARNING and "clipped" in e[3]]) == 1
    finally:
        net.close()
    assert np.allclose(read(tmp_path / "x.jpg")[1], [[0, 0.5, 1]], atol=0.03)


def test_needs_a_filename_and_a_connected_image(tmp_path):
    with pytest.raises(ModelError, match="needs a filename"):
        load(tmp_path, '<module class="OutputJPEG" name="O"/>')
    with pytest.raises(ModelError, match="connect INPUT, INTENSITY"):
        load(tmp_path, '<module class="OutputJPEG" name="O" filename="x.jpg"/>')


def test_unwritable_file_warns_and_the_run_goes_on(tmp_path):
    (tmp_path / "nofolder").write_text("a file where the folder would be")
    net = load(tmp_path, '<module class="Constant" name="C" data="0.5"/>\n'
                         '<module class="OutputJPEG" name="O" filename="nofolder/x.jpg"/>\n'
                         '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert net.tick == 3
        assert len([e for e in net.log if e[1] == WARNING and "cannot write" in e[3]]) == 1
    finally:
        net.close()
