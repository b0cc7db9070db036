"""Tests of the Normalize module."""

import numpy as np
import pytest

from ikaros.module import WARNING
from ikaros.testing import load_body as load


def normalize(tmp_path, data, kind):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="Normalize" name="N" type="{kind}"/>'
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>')
    try:
        net.step()
        return net.output("N.OUTPUT"), [e for e in net.log if e[1] == WARNING]
    finally:
        net.close()


@pytest.mark.parametrize("kind, expected", [
    ("range", [[0, 0.25], [0.5, 1]]),        # (x - 2) / 4
    ("euclidean", np.array([[2, 3], [4, 6]]) / np.sqrt(65.0)),    # |x|^2 = 4+9+16+36
    ("cityblock", [[2 / 15, 3 / 15], [4 / 15, 6 / 15]]),
    ("max", [[2 / 6, 3 / 6], [4 / 6, 1]]),
])
def test_hand_worked(tmp_path, kind, expected):
    out, warnings = normalize(tmp_path, "2 3; 4 6", kind)
    assert out.shape == (2, 2) and out.dtype == np.float32
    assert np.allclose(out, expected, atol=1e-6)
    assert not warnings


def test_negative_values(tmp_path):
    out, _ = normalize(tmp_path, "-3 1 -1", "cityblock")
    assert np.allclose(out, [-0.6, 0.2, -0.2])
    out, _ = normalize(tmp_path, "-3 1 -1", "range")
    assert np.allclose(out, [0, 1, 0.5])
    out, _ = normalize(tmp_path, "3 -4", "euclidean")
    assert np.allclose(out, [0.6, -0.8])


@pytest.mark.parametrize("kind, data", [("range", "2 2 2"), ("euclidean", "0 0"),
                                        ("cityblock", "0 0"), ("max", "-1 0")])
def test_zero_divisor_gives_zero_and_one_warning(tmp_path, kind, data):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="Normalize" name="N" type="{kind}"/>'
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        out = net.output("N.OUTPUT")
        assert np.all(out == 0)
        assert len([e for e in net.log if e[1] == WARNING]) == 1
    finally:
        net.close()


def test_random_input_over_several_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="8" min="-1" seed="9"/>'
                         '<module class="Normalize" name="N"/>'
                         '<module class="Normalize" name="E" type="euclidean"/>'
                         '<connection source="R.OUTPUT" target="N.INPUT" delay="0"/>'
                         '<connection source="R.OUTPUT" target="E.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            r = net.output("R.OUTPUT").astype(np.float64)
            assert np.allclose(net.output("N.OUTPUT"), (r - r.min()) / (r.max() - r.min()),
                               atol=1e-6)
            assert np.allclose(net.output("E.OUTPUT"), r / np.linalg.norm(r), atol=1e-6)
    finally:
        net.close()


def test_float32_extremes_normalise_without_overflow(tmp_path):
    out, warnings = normalize(tmp_path, "-3e38 3e38 0", "range")
    assert out.tolist() == [0, 1, 0.5] and warnings == []
