"""Tests of the Map module."""
import numpy as np

from ikaros.testing import load_body as load


def test_maps_ranges_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="3" '
               'outputsize_y="2" min="-10" max="370" seed="1"/>'
               '<module class="Map" name="M" low_source="0" high_source="360" '
               'low_target="1" high_target="-1"/>'
               '<connection source="R.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            assert np.allclose(net.output("M.OUTPUT"), 1 + (x - 0) * (-2 / 360), atol=1e-6)
    finally:
        net.close()


def test_hand_worked_and_extrapolates(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 5 10 20 -10"/>'
               '<module class="Map" name="M" low_source="0" high_source="10" '
               'low_target="100" high_target="200"/>'
               '<module class="Map" name="D"/>'
               '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="D.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("M.OUTPUT"), [100, 150, 200, 300, 0])
        assert np.allclose(net.output("D.OUTPUT"), [0, 5, 10, 20, -10])     # defaults: copy
    finally:
        net.close()


def test_empty_source_range_gives_low_target_and_warns_once(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2"/>'
               '<module class="Map" name="M" low_source="3" high_source="3" '
               'low_target="7"/>'
               '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("M.OUTPUT"), [7, 7])
        assert np.all(np.isfinite(net.output("M.OUTPUT")))
        assert sum("low_target" in entry[3] for entry in net.log) == 1
    finally:
        net.close()
