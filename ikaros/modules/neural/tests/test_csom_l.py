"""Tests of the CSOM_L module."""
import numpy as np
import pytest

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text


def test_forms_an_ordered_chain_along_a_line(tmp_path):
    # a 1 x 8 map of a 1-D input: the units must end up in order along the line
    net = load(tmp_path,
               '<module class="Randomizer" name="R" outputsize="1" seed="2"/>'
               '<module class="CSOM_L" name="S" rf_size_x="1" rf_size_y="1" som_size_x="8" '
               'som_size_y="1" use_arbor="no" alpha="0.2" alpha_max="0.2" alpha_min="0.02" '
               'alpha_decay="0.999" sigma="0.5" sigma_min="0.05" sigma_decay="0.997" seed="7"/>'
               '<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        start = net.output("S.WEIGHTS").ravel().copy()
        net.run(ticks=2000)
        w = net.output("S.WEIGHTS").ravel()
        steps = np.diff(w)
        assert np.all(steps > 0) or np.all(steps < 0)        # a topographic (ordered) map
        assert not (np.all(np.diff(start) > 0) or np.all(np.diff(start) < 0))
        assert np.allclose(np.sort(w), (np.arange(8) + 0.5) / 8, atol=0.05)
        dist = net.output("S.STAT_DISTRIBUTION")
        assert dist.shape == (1, 8) and dist.sum() == pytest.approx(1)
    finally:
        net.close()


def test_salience_map_size_and_weight_files(tmp_path):
    image = (np.arange(35).reshape(5, 7) * 7 % 11) / 11
    W = np.random.default_rng(1).random((4, 9))
    np.savetxt(tmp_path / "in.txt", W.ravel())
    net = load(tmp_path,
               f'<module class="Constant" name="I" data="{matrix_text(image, ".9g")}"/>'
               '<module class="CSOM_L" name="S" rf_inc_x="2" rf_inc_y="2" som_size_x="2" '
               'som_size_y="2" alpha="0" alpha_min="0" read_file="in.txt" '
               'write_file="out.txt"/>'
               '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        # (7 - 3) // 2 + 1 = 3 fields across, (5 - 3) // 2 + 1 = 2 down
        assert net.output("S.SALIENCE").shape == (2, 3)
        assert net.output("S.OUTPUT").shape == (2 * 2, 3 * 2)
        assert net.output("S.WEIGHTS").shape == (6, 6)
        net.step()
        y = (np.arange(3) - 1) / 1.75
        arbor = np.maximum(0, 1 - y[:, None] ** 2 - y[None, :] ** 2).ravel()
        X = np.array([image[2 * j:2 * j + 3, 2 * i:2 * i + 3].ravel()
                      for j in range(2) for i in range(3)])
        mse = ((X[:, None] - W[None]) ** 2 @ arbor) / arbor.sum()
        act = 1 / (1 + mse)
        assert np.allclose(net.output("S.SALIENCE"), act.sum(1).reshape(2, 3), rtol=1e-5)
        assert np.allclose(net.output("S.OUTPUT"),
                           act.reshape(2, 3, 2, 2).transpose(0, 2, 1, 3).reshape(4, 6),
                           rtol=1e-5)
    finally:
        net.close()
    assert np.allclose(np.loadtxt(tmp_path / "out.txt"), W.ravel(), atol=1e-6)


def test_sigma_and_alpha_decay_between_limits(tmp_path):
    # one unit moving towards a constant input: w(t+1) = w + alpha(t) (x - w)
    net = load(tmp_path,
               '<module class="Constant" name="I" data="1"/>'
               '<module class="CSOM_L" name="S" rf_size_x="1" rf_size_y="1" som_size_x="1" '
               'som_size_y="1" use_arbor="no" alpha="0.4" alpha_max="0.5" alpha_min="0.1" '
               'alpha_decay="0.5" seed="3"/>'
               '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        w = float(net.output("S.WEIGHTS")[0, 0])
        alpha = 0.4
        for _ in range(5):
            error = 1 - w                                    # before the tick's learning
            w += alpha * (1 - w)
            alpha = max(alpha * 0.5, 0.1)
            net.step()
            assert net.output("S.WEIGHTS")[0, 0] == pytest.approx(w, rel=1e-5)
            assert net.output("S.ERROR")[0] == pytest.approx(error, rel=1e-4)
    finally:
        net.close()
