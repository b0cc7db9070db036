"""Tests of the Noise module."""

import numpy as np

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
                         '<connection source="C.OUTPUT" target="N.INPUT" delay="0"/>')
    try:
        net.step()
        out = net.output("N.OUTPUT")
        assert abs(out.mean() - 3) < 0.2 and abs(out.std() - 2) < 0.2
    finally:
        net.close()
