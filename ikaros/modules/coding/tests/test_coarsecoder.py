"""Tests of the CoarseCoder module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def position(v, n, r, lo=0.0, hi=1.0):
    return r + (n - 1 - 2 * r) * (np.clip(v, lo, hi) - lo) / (hi - lo)


def tile(v, n, r, normalize=False):
    out = np.zeros((n, n))
    px, py = position(np.asarray(v, dtype=np.float64), n, r)
    for j in range(n):
        for i in range(n):
            if np.floor(px - r + 0.5) <= i <= np.floor(px + r + 0.5) and \
                    np.floor(py - r + 0.5) <= j <= np.floor(py + r + 0.5):
                out[j, i] = 1
    return out / out.sum() if normalize else out


def gaussian(v, n, r, normalize=False, profile="distance"):
    px, py = position(np.asarray(v, dtype=np.float64), n, r)
    j, i = np.mgrid[0:n, 0:n]
    d2 = (i - px) ** 2 + (j - py) ** 2
    out = np.exp(-np.sqrt(d2)) if profile == "distance" else np.exp(-d2 / (2 * r * r))
    return out / out.sum() if normalize else out


RANDOM = ('<module class="Randomizer" name="R" outputsize="2" seed="8"/>\n'
          '<connection source="R.OUTPUT" target="C.INPUT" delay="0"/>\n')


@pytest.mark.parametrize("normalize", [False, True])
def test_tile_over_ticks(tmp_path, normalize):
    net = load(tmp_path, RANDOM + f'<module class="CoarseCoder" name="C" output_size="8" '
                                  f'radius="1" normalize="{normalize}"/>')
    try:
        assert net.output("C.OUTPUT").shape == (8, 8)
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT")
            y = net.output("C.OUTPUT")
            assert np.allclose(y, tile(x, 8, 1, normalize), atol=1e-6)
            assert np.count_nonzero(y) == 9
    finally:
        net.close()


@pytest.mark.parametrize("profile", ["distance", "normal"])
@pytest.mark.parametrize("normalize", [False, True])
def test_gaussian_over_ticks(tmp_path, normalize, profile):
    net = load(tmp_path, RANDOM + f'<module class="CoarseCoder" name="C" type="gaussian" '
                                  f'output_size="7" radius="1.5" normalize="{normalize}" '
                                  f'profile="{profile}"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT")
            assert np.allclose(net.output("C.OUTPUT"),
                               gaussian(x, 7, 1.5, normalize, profile), atol=1e-6)
    finally:
        net.close()


def test_hand_worked_ikaros2_gaussian(tmp_path):
    # 3 x 3, radius 0: x = 0.5 -> column 1, y = 0 -> row 0; each cell is exp(-distance)
    net = load(tmp_path, '<module class="Constant" name="K" data="0.5 0"/>\n'
                         '<module class="CoarseCoder" name="C" type="gaussian" output_size="3" '
                         'radius="0"/>\n'
                         '<connection source="K.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        net.step()
        e = np.exp
        r2 = np.sqrt(2)
        assert np.allclose(net.output("C.OUTPUT"), [[e(-1), 1, e(-1)],
                                                    [e(-r2), e(-1), e(-r2)],
                                                    [e(-np.sqrt(5)), e(-2), e(-np.sqrt(5))]])
    finally:
        net.close()


def test_hand_worked_corners_and_clipping(tmp_path):
    # min=-1, max=1, 5 x 5, radius 1: x=-1 -> column 1 (tile columns 0..2), y=5 (clipped
    # to 1) -> row 3 (tile rows 2..4)
    net = load(tmp_path, '<module class="Constant" name="K" data="-1 5"/>\n'
                         '<module class="CoarseCoder" name="C" output_size="5" min="-1"/>\n'
                         '<connection source="K.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        net.step()
        expected = np.zeros((5, 5))
        expected[2:5, 0:3] = 1
        assert np.array_equal(net.output("C.OUTPUT"), expected)
    finally:
        net.close()


def test_radius_0_and_equal_min_max(tmp_path):
    body = ('<module class="Constant" name="K" data="0.5 1"/>\n'
            '<module class="CoarseCoder" name="C" output_size="5" radius="0" type="gaussian" '
            'profile="normal"/>\n'
            '<module class="CoarseCoder" name="E" output_size="5" min="2" max="2"/>\n'
            '<connection source="K.OUTPUT" target="C.INPUT" delay="0"/>\n'
            '<connection source="K.OUTPUT" target="E.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.run(ticks=2)
        expected = np.zeros((5, 5))
        expected[4, 2] = 1                     # x: 0 + 4 * 0.5 = 2; y: 4
        assert np.array_equal(net.output("C.OUTPUT"), expected)
        expected = np.zeros((5, 5))
        expected[0:3, 0:3] = 1                 # every value codes as min
        assert np.array_equal(net.output("E.OUTPUT"), expected)
        warnings = [m for (_, level, where, m) in net.log if where == "E" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()


def test_input_must_have_two_elements(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="K" data="1 2 3"/>\n'
                       '<module class="CoarseCoder" name="C"/>\n'
                       '<connection source="K.OUTPUT" target="C.INPUT"/>')
