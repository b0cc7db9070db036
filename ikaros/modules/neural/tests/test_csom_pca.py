"""Tests of the CSOM_PCA module."""
import numpy as np
import pytest

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text


def test_one_unit_learns_the_first_principal_component(tmp_path):
    rng = np.random.default_rng(0)
    axes = np.linalg.qr(rng.standard_normal((3, 3)))[0]
    samples = (rng.standard_normal((300, 3)) * [1.0, 0.4, 0.2]) @ axes.T
    net = load(tmp_path,
               f'<module class="ListIterator" name="D" listdata="{matrix_text(samples, ".9g")}" '
               'repeat="yes"/>'
               '<module class="CSOM_PCA" name="S" rf_size_x="3" rf_size_y="1" som_size_x="1" '
               'som_size_y="1" alpha="0.02" alpha_max="0.02" alpha_min="0.002" '
               'alpha_decay="0.999" seed="5"/>'
               '<connection source="D.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.run(ticks=3000)
        w = net.output("S.WEIGHTS").ravel()
        first = np.linalg.eigh(np.cov(samples.T))[1][:, -1]
        assert np.linalg.norm(w) == pytest.approx(1, abs=0.05)           # Oja: unit length
        assert abs(w @ first) / np.linalg.norm(w) > 0.99
    finally:
        net.close()


def test_activity_is_the_dot_product_and_reconstruction(tmp_path):
    image = np.array([[0.2, 0.9, 0.4, 0.1], [0.5, 0.3, 0.8, 0.6]])
    top = np.array([[1, 0, 0.5, 2, 0, 1]])            # 1 x 3 fields, 2 units each (combined)
    net = load(tmp_path,
               f'<module class="Constant" name="I" data="{matrix_text(image, ".9g")}"/>'
               f'<module class="Constant" name="T" data="{matrix_text(top, ".9g")}"/>'
               '<module class="CSOM_PCA" name="S" rf_size_x="2" rf_size_y="2" som_size_x="2" '
               'som_size_y="1" alpha="0" alpha_min="0" seed="1"/>'
               '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>'
               '<connection source="T.OUTPUT" target="S.TOP_DOWN" delay="0"/>')
    try:
        net.step()
        W = net.output("S.WEIGHTS").reshape(2, 2, 2).transpose(1, 0, 2).reshape(2, 4)
        assert np.allclose(np.linalg.norm(W, axis=1), 1, atol=1e-5)       # random unit vectors
        X = np.array([image[:, i:i + 2].ravel() for i in range(3)])
        act = X @ W.T                                                      # (fields, units)
        assert np.allclose(net.output("S.OUTPUT"), act.reshape(1, 6), atol=1e-6)
        recon, count = np.zeros((2, 4)), np.zeros((2, 4))
        td = top.reshape(3, 2)
        for i in range(3):
            k = np.abs(td[i]).argmax()                      # the unit with the largest |td|
            recon[:, i:i + 2] += (td[i, k] * W[k]).reshape(2, 2)
            count[:, i:i + 2] += 1
        assert np.allclose(net.output("S.RECONSTRUCTION"), recon / count, atol=1e-6)
        best = act.argmax(1)
        y = act[np.arange(3), best]
        err = np.sqrt(np.mean((X - y[:, None] * W[best]) ** 2))
        assert net.output("S.ERROR")[0] == pytest.approx(err, rel=1e-5)
    finally:
        net.close()


def test_neighbouring_units_learn_neighbouring_directions(tmp_path):
    # points on lines through the origin at angles 0..180 degrees: each unit learns an
    # orientation, and the chain of units orders the orientations
    rng = np.random.default_rng(1)
    theta = rng.uniform(0, np.pi, 400)
    r = rng.standard_normal(400)
    samples = np.stack([r * np.cos(theta), r * np.sin(theta)], axis=1)
    net = load(tmp_path,
               f'<module class="ListIterator" name="D" listdata="{matrix_text(samples, ".9g")}" '
               'repeat="yes"/>'
               '<module class="CSOM_PCA" name="S" rf_size_x="2" rf_size_y="1" som_size_x="6" '
               'som_size_y="1" alpha="0.05" alpha_max="0.05" alpha_min="0.005" '
               'alpha_decay="0.999" sigma="0.5" sigma_min="0.05" sigma_decay="0.999" '
               'topology="torus" seed="2"/>'
               '<connection source="D.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.run(ticks=4000)
        W = net.output("S.WEIGHTS").reshape(6, 2)
        angles = np.arctan2(W[:, 1], W[:, 0]) % np.pi                   # orientation of each
        gaps = (np.diff(np.append(angles, angles[0])) + np.pi / 2) % np.pi - np.pi / 2
        # on the ring, each step between neighbours turns the same way by about 30 degrees
        assert np.all(gaps > 0.2) or np.all(gaps < -0.2), np.degrees(gaps)
        assert np.allclose(np.linalg.norm(W, axis=1), 1, atol=0.1)
    finally:
        net.close()
