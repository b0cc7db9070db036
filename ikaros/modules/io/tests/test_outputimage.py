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
