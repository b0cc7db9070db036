"""Tests of the OutputPNG module: 8-bit levels are exact, so files round-trip."""
import numpy as np
from PIL import Image

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text


def test_gray_levels_round_to_nearest(tmp_path):
    values = np.array([[0, 0.5 / 255 - 1e-4, 0.5 / 255 + 1e-4, 0.5], [1, 0.2, 0.999, 1e-3]])
    net = load(tmp_path, f'<module class="Constant" name="C" data="{matrix_text(values)}"/>\n'
                         '<module class="OutputPNG" name="O" filename="g.png"/>\n'
                         '<connection source="C.OUTPUT" target="O.INTENSITY" delay="0"/>')
    try:
        net.step()
    finally:
        net.close()
    with Image.open(tmp_path / "g.png") as img:
        assert img.mode == "L"
        got = np.asarray(img)
    expected = np.rint(np.float32(values) * 255).astype(np.uint8)
    assert np.array_equal(got, expected)
    assert got[0, 1] == 0 and got[0, 2] == 1 and got[0, 3] == 128


def test_colour_input_round_trips_through_inputpng(tmp_path):
    rgb = np.random.default_rng(5).integers(0, 256, (4, 6, 3)).astype(np.uint8)
    Image.fromarray(rgb, "RGB").save(tmp_path / "in.png")
    net = load(tmp_path, '<module class="InputPNG" name="I" filename="in.png"/>\n'
                         '<module class="OutputPNG" name="O" filename="out%d.png"/>\n'
                         '<connection source="I.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=2)
    finally:
        net.close()
    for k in range(2):
        with Image.open(tmp_path / f"out{k}.png") as img:
            assert img.mode == "RGB"
            assert np.array_equal(np.asarray(img), rgb)


def test_red_green_blue_planes(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="R" data="1 0; 0 0"/>\n'
                         '<module class="Constant" name="G" data="0 1; 0 0"/>\n'
                         '<module class="Constant" name="B" data="0 0; 1 0.5"/>\n'
                         '<module class="OutputPNG" name="O" filename="c.png"/>\n'
                         '<connection source="R.OUTPUT" target="O.RED" delay="0"/>\n'
                         '<connection source="G.OUTPUT" target="O.GREEN" delay="0"/>\n'
                         '<connection source="B.OUTPUT" target="O.BLUE" delay="0"/>')
    try:
        net.step()
    finally:
        net.close()
    with Image.open(tmp_path / "c.png") as img:
        got = np.asarray(img)
    assert got[0, 0].tolist() == [255, 0, 0] and got[0, 1].tolist() == [0, 255, 0]
    assert got[1, 0].tolist() == [0, 0, 255] and got[1, 1].tolist() == [0, 0, 128]


def test_without_counter_the_file_holds_the_last_image(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" outputsize_x="2" outputsize_y="2" '
                         'min="0" max="1" step="0.25"/>\n'
                         '<module class="OutputPNG" name="O" filename="last.png"/>\n'
                         '<connection source="S.OUTPUT" target="O.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
    finally:
        net.close()
    assert [p.name for p in tmp_path.glob("*.png")] == ["last.png"]
    with Image.open(tmp_path / "last.png") as img:
        assert np.all(np.asarray(img) == 191)                # round(0.75 * 255)
