"""Tests of the Randomizer module."""

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load



def draws(seed, shape, low, high, n):
    """What the module should produce: n draws (init first) from default_rng(seed)."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        a = np.empty(shape, np.float32)
        rng.random(out=a, dtype=np.float32)
        a *= np.float32(high - low)
        a += np.float32(low)
        out.append(a)
    return out


def test_seeded_values_every_tick(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" seed="42" outputsize="5" '
                         'min="-1" max="3"/>')
    try:
        expected = draws(42, (5,), -1, 3, 6)
        assert np.array_equal(net.output("R.OUTPUT"), expected[0])     # init
        for tick in range(5):
            net.step()
            out = net.output("R.OUTPUT")
            assert out.dtype == np.float32
            assert np.array_equal(out, expected[tick + 1]), tick
            assert np.all(out >= -1) and np.all(out < 3)
    finally:
        net.close()


def test_interval_keeps_values_between_draws(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" seed="7" outputsize_x="3" '
                         'outputsize_y="2" interval="3"/>', dialect=2)   # ticks from 0
    try:
        expected = draws(7, (2, 3), 0, 1, 4)
        assert net.output("R.OUTPUT").shape == (2, 3)
        # draws: init, tick 0, tick 3, tick 6
        which = [1, 1, 1, 2, 2, 2, 3]
        for tick in range(7):
            net.step()
            assert np.array_equal(net.output("R.OUTPUT"), expected[which[tick]]), tick
    finally:
        net.close()


def test_same_seed_same_run_other_seed_other_run(tmp_path):
    runs = []
    for seed in ("5", "5", "6"):
        net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="20"/>', seed=seed)
        try:
            net.run(ticks=3)
            runs.append(net.output("R.OUTPUT"))
        finally:
            net.close()
    assert np.array_equal(runs[0], runs[1])
    assert not np.array_equal(runs[0], runs[2])


def test_unseeded_default_size_and_range(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R"/>')
    try:
        values = []
        for _ in range(50):
            net.step()
            out = net.output("R.OUTPUT")
            assert out.shape == (1,)
            values.append(out[0])
        values = np.array(values)
        assert np.all(values >= 0) and np.all(values < 1)
        assert len(np.unique(values)) > 40
    finally:
        net.close()


def test_bounds_must_be_finite(tmp_path):
    """As Ikaros 3: an infinite or NaN bound is an error."""
    for attrs in ('max="inf"', 'min="nan"'):
        with pytest.raises(ModelError, match=r"is not a finite number"):
            load(tmp_path, f'<module class="Randomizer" name="R" {attrs}/>')


def test_a_range_wider_than_float32_does_not_overflow(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" min="-3e38" max="3e38" '
                         'outputsize="1000" seed="2"/>')
    try:
        net.step()
        out = net.output("R.OUTPUT")
        assert np.all(np.isfinite(out))
        assert out.min() < -1e38 and out.max() > 1e38
    finally:
        net.close()


@pytest.mark.parametrize("attrs, dialect, shape", [
    ("", "3", (2, 3)),                      # IKAROS3-INTERFACES: size "2,3"
    ('size="4"', "3", (4,)),
    ('size="3,4"', "2", (3, 4)),
    ('outputsize="5"', "3", (5,)),          # an Ikaros 2 size set in the file wins
    ("", "2", (1,)),
])
def test_size_gives_the_shape(tmp_path, attrs, dialect, shape):
    net = load(tmp_path, f'<module class="Randomizer" name="R" seed="3" {attrs}/>',
               dialect=dialect)
    with net:
        assert net.output("R.OUTPUT").shape == shape
        net.step()
        assert np.array_equal(net.output("R.OUTPUT"), draws(3, shape, 0, 1, 2)[1])


def test_ikaros_3_default_seed_gives_a_different_run_every_time(tmp_path):
    runs = []
    for _ in range(2):
        with load(tmp_path, '<module class="Randomizer" name="R" size="50"/>',
                  dialect="3") as net:
            assert net.parameter("R.seed") == -1
            net.step()
            runs.append(net.output("R.OUTPUT"))
    assert not np.array_equal(runs[0], runs[1])
