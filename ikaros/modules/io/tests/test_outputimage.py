"""Tests of the OutputImage module (Ikaros 3's image writer)."""
import numpy as np
import pytest
from PIL import Image

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

GRAY = '<module class="Constant" name="C" data="0 0.5; 1 0.25"/>\n'


def write(tmp_path, attrs, ticks=2, source=GRAY):
    net = load(tmp_path, source + f'<module class="OutputImage" name="O" {attrs}/>\n'
                                  '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=ticks)
    finally:
        net.close()


def test_png_by_extension_with_hash_numbers(tmp_path):
    write(tmp_path, 'filename="g_##.png"')
    for k in (0, 1):
        with Image.open(tmp_path / f"g_{k:02d}.png") as img:
            assert img.format == "PNG"
            assert np.asarray(img).tolist() == [[0, 128], [255, 64]]
    assert not (tmp_path / "g_02.png").exists()


def test_jpeg_by_extension_and_by_format(tmp_path):
    write(tmp_path, 'filename="a.jpg"', ticks=1)
    write(tmp_path, 'filename="b.img" format="jpeg"', ticks=1)
    for name in ("a.jpg", "b.img"):
        with Image.open(tmp_path / name) as img:
            assert img.format == "JPEG"
            assert np.allclose(np.asarray(img, float), [[0, 128], [255, 64]], atol=3)


def test_unknown_extension_without_format_is_an_error(tmp_path):
    with pytest.raises(ModelError, match='cannot tell the image format of "a.img"'):
        write(tmp_path, 'filename="a.img"')


def test_start_index_directory_and_single_trigger(tmp_path):
    (tmp_path / "w.txt").write_text("W/1\n1\n1\n0\n1\n")
    net = load(tmp_path, GRAY + '<module class="InputFile" name="W" filename="w.txt"/>'
                                '<module class="OutputImage" name="O" filename="t_#.png" '
                                'directory="shots" start_index="3" single_trigger="yes"/>'
                                '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>'
                                '<connection source="W.W" target="O.WRITE" delay="0"/>')
    try:
        net.run(ticks=4)
    finally:
        net.close()
    assert sorted(p.name for p in (tmp_path / "shots").iterdir()) == ["t_3.png", "t_6.png"]


def test_ikaros_3_defaults_write_output_jpg_at_quality_90(tmp_path):
    import io
    net = load(tmp_path, GRAY + '<module class="OutputImage" name="O"/>'
                                '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>',
               dialect="3")
    try:
        net.run(ticks=1)
    finally:
        net.close()
    expected = io.BytesIO()
    Image.fromarray(np.uint8([[0, 128], [255, 64]]), "L").save(expected, format="JPEG",
                                                                quality=90)
    assert (tmp_path / "output.jpg").read_bytes() == expected.getvalue()
