"""Tests of the Noise module."""

import numpy as np
import pytest

import ikaros

from ikaros.testing import load_body as load

BODY = ('<module class="Constant" name="C" data="1 2 3; 4 5 6"/>'
        '<module class="Noise" name="N" {attrs}/>'
        '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>')


def run(tmp_path, attrs, ticks):
    net = load(tmp_path, BODY.format(attrs=attrs))
    try:
        outs = []
        for _ in range(ticks):
            net.step()
            outs.append(net.output("N.OUTPUT"))
        return np.array(outs)
    finally:
        net.close()


def test_same_seed_gives_the_same_noise_as_numpy(tmp_path):
    outs = run(tmp_path, 'seed="42" sigma="0.5" mean="2"', 3)
    assert outs.shape == (3, 2, 3) and outs.dtype == np.float32
    rng = np.random.default_rng(42)
    data = np.array([[1, 2, 3], [4, 5, 6]], np.float32)
    for out in outs:
        noise = rng.standard_normal((2, 3), dtype=np.float32)
        expected = noise * np.float32(0.5) + np.float32(2) + data
        assert np.allclose(out, expected, atol=1e-6)
    assert not np.array_equal(outs[0], outs[1])          # new noise on every tick


def test_same_seed_same_run(tmp_path):
    a = run(tmp_path, 'seed="5"', 4)
    b = run(tmp_path, 'seed="5"', 4)
    assert np.array_equal(a, b)


def test_sigma_zero_adds_only_the_mean(tmp_path):
    outs = run(tmp_path, 'sigma="0" mean="-1"', 2)
    assert np.array_equal(outs[-1], [[0, 1, 2], [3, 4, 5]])


def test_statistics(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" outputsize="2000" data="0"/>'
                         '<module class="Noise" name="N" sigma="2" mean="3" seed="1"/>'
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>',
               dialect="2")
    try:
        net.step()
        out = net.output("N.OUTPUT")
        assert abs(out.mean() - 3) < 0.2 and abs(out.std() - 2) < 0.2
    finally:
        net.close()


# --- Ikaros 3: uniform noise, type by name or index ---------------------------------------------
def _uniform(seed, low, high, shape=(2, 3)):
    rng = np.random.default_rng(seed)
    data = np.array([[1, 2, 3], [4, 5, 6]], np.float32)
    while True:
        draw = rng.random(shape, dtype=np.float32)
        yield (low + draw.astype(np.float64) * (high - low)).astype(np.float32) + data


@pytest.mark.parametrize("attrs", ['type="uniform" min="-0.5" max="2"',
                                   'type="1" min="2" max="-0.5"'])
def test_uniform_noise_between_the_bounds_in_either_order(tmp_path, attrs):
    outs = run(tmp_path, f'{attrs} seed="7"', 3)
    for out, expected in zip(outs, _uniform(7, -0.5, 2.0)):
        assert np.allclose(out, expected, atol=1e-6)
    noise = outs - np.array([[1, 2, 3], [4, 5, 6]], np.float32)
    assert noise.min() >= -0.5 and noise.max() < 2


def test_gaussian_by_name_or_index_is_the_same(tmp_path):
    assert np.array_equal(run(tmp_path, 'type="gaussian" seed="3"', 2),
                          run(tmp_path, 'type="0" seed="3"', 2))


@pytest.mark.parametrize("attrs, message", [
    ('type="uniform" min="nan"', 'parameter "min" of N: nan is not a finite number'),
    ('max="inf"', 'parameter "max" of N: inf is not a finite number'),
    ('sigma="-1"', 'parameter "sigma" of N: -1 is below minimum 0'),
    ('type="pink"', '"pink" is not one of gaussian/uniform'),
])
def test_bad_settings_are_errors_at_load(tmp_path, attrs, message):
    with pytest.raises(ikaros.ModelError, match=message):
        run(tmp_path, attrs, 1)


def test_bad_bounds_while_running_are_refused_and_the_last_valid_ones_stay(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" outputsize="500" data="0"/>'
                         '<module class="Noise" name="N" type="uniform" min="0" max="1"/>'
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>')
    try:
        net.set_parameter("N.max", 3)
        net.step()
        with pytest.raises(ValueError, match='bad value for parameter "N.min": nan is not a '
                                             'finite number'):
            net.set_parameter("N.min", "nan")
        net.step()
        out = net.output("N.OUTPUT")
        assert net.parameter("N.min") == 0 and net.parameter("N.max") == 3
        assert out.min() >= 0 and out.max() < 3 and out.max() > 1
    finally:
        net.close()


# --- Ikaros 3's interface (IKAROS3-INTERFACES: type uniform, min -0.1, max 0.1, stddev 0.1) --
def _run_v3(tmp_path, attrs, ticks=1):
    net = load(tmp_path, '<module class="Constant" name="C" outputsize="4000" data="0"/>'
                         f'<module class="Noise" name="N" {attrs}/>'
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>',
               dialect="3")
    with net:
        net.run(ticks=ticks)
        return net.output("N.OUTPUT").astype(np.float64), net.parameter("N.type")


def test_ikaros_3_defaults_are_uniform_within_a_tenth(tmp_path):
    out, kind = _run_v3(tmp_path, "")
    assert kind == "uniform"
    assert out.min() >= -0.1 and out.max() < 0.1
    assert abs(out.mean()) < 0.01 and abs(out.std() - 0.2 / np.sqrt(12)) < 0.005


def test_ikaros_3_gaussian_uses_stddev(tmp_path):
    out, _ = _run_v3(tmp_path, 'type="gaussian" mean="1"')          # stddev 0.1
    assert abs(out.mean() - 1) < 0.01 and abs(out.std() - 0.1) < 0.01
    out, _ = _run_v3(tmp_path, 'type="gaussian" stddev="2" seed="5"')
    assert abs(out.std() - 2) < 0.1
    rng = np.random.default_rng(5)
    assert np.allclose(out, rng.standard_normal(4000, dtype=np.float32) * np.float32(2))


def test_ikaros_2_uses_sigma_or_a_stddev_the_module_sets(tmp_path):
    rng = np.random.default_rng(9)
    noise = rng.standard_normal((2, 3), dtype=np.float32)
    data = np.array([[1, 2, 3], [4, 5, 6]], np.float32)
    out = run(tmp_path, 'seed="9" sigma="3"', 1)[0]
    assert np.allclose(out, noise * np.float32(3) + data, atol=1e-6)
    out = run(tmp_path, 'seed="9" sigma="3" stddev="0.5"', 1)[0]
    assert np.allclose(out, noise * np.float32(0.5) + data, atol=1e-6)
