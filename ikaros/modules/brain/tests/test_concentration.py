"""Tests of the Concentration module (Ikaros 3, MODULES-V3 §13)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def test_without_input_the_level_stays_at_the_floor(tmp_path):
    # MODULES-V3 §13 [oracle]: tick_duration 0.5 and no input: 0.125
    net = load(tmp_path, '<module class="Concentration" name="H"/>', tick_duration="0.5")
    try:
        for _ in range(3):
            net.step()
            assert net.output("H.OUTPUT")[0] == np.float32(0.125)
    finally:
        net.close()


def test_rises_with_input_and_decays_towards_the_floor(tmp_path):
    (tmp_path / "x.txt").write_text("X/2\n2 2\n0 0\n0 0\n0 0\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="x.txt"/>'
                         '<module class="Concentration" name="H" alpha="0.5" beta="2" '
                         'gamma="1"/>'
                         '<connection source="F.X" target="H.INPUT" delay="0"/>',
               tick_duration="0.1")
    try:
        floor, y, got, expected = 0.1, 0.1, [], []
        for x in (4, 0, 0, 0):
            y = max(y + 0.5 * x - 2 * 0.1 * (y - floor), floor)
            expected.append(y)
            net.step()
            got.append(float(net.output("H.OUTPUT")[0]))
        assert got == pytest.approx(expected, rel=1e-6)
    finally:
        net.close()
