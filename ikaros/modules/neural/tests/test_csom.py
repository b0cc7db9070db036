"""Tests of the CSOM module (convolutional self-organising map)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text


def unit_weights(weights, sy, sx, ry, rx):
    """WEIGHTS (laid out as the map) -> (units, field elements)."""
    return weights.reshape(sy, ry, sx, rx).transpose(0, 2, 1, 3).reshape(sy * sx, ry * rx)


def fields(image, ry, rx, iy=1, ix=1):
    rows, cols = image.shape
    my, mx = (rows - ry) // iy + 1, (cols - rx) // ix + 1
    return np.array([image[j * iy:j * iy + ry, i * ix:i * ix + rx].ravel()
                     for j in range(my) for i in range(mx)]), my, mx


def topographic_error(W, sy, sx, samples):
    d = ((samples[:, None, :] - W[None]) ** 2).sum(-1)
    order = np.argsort(d, axis=1)
    y1, x1 = np.divmod(order[:, 0], sx)
    y2, x2 = np.divmod(order[:, 1], sx)
    return np.mean(np.maximum(abs(y1 - y2), abs(x1 - x2)) > 1)


SOM = ('<module class="Randomizer" name="R" outputsize="2" seed="3"/>'
       '<module class="CSOM" name="S" rf_size_x="2" rf_size_y="1" som_size_x="6" '
       'som_size_y="6" use_arbor="no" alpha="0.3" alpha_max="0.3" alpha_min="0.01" '
       'alpha_decay="0.999" '
       'sigma="0.5" sigma_min="0.05" sigma_decay="0.998" seed="1"/>'
       '<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>')


def test_forms_a_topographic_map_of_the_unit_square(tmp_path):
    net = load(tmp_path, SOM)
    try:
        samples = np.random.default_rng(5).random((2000, 2))
        W0 = unit_weights(net.output("S.WEIGHTS"), 6, 6, 1, 2).copy()
        assert topographic_error(W0, 6, 6, samples) > 0.3        # random start: no order
        net.run(ticks=3000)
        W = unit_weights(net.output("S.WEIGHTS"), 6, 6, 1, 2)
        assert topographic_error(W, 6, 6, samples) < 0.02
        quantisation = np.sqrt(((samples[:, None] - W[None]) ** 2).sum(-1).min(1)).mean()
        assert quantisation < 0.09
        # neighbouring units have neighbouring weight vectors
        grid = W.reshape(6, 6, 2)
        step = np.concatenate([np.linalg.norm(np.diff(grid, axis=0), axis=-1).ravel(),
                               np.linalg.norm(np.diff(grid, axis=1), axis=-1).ravel()])
        assert step.max() < 0.3 and step.mean() < 0.2
        dist = net.output("S.STAT_DISTRIBUTION")
        assert dist.shape == (6, 6) and dist.sum() == pytest.approx(1) and np.all(dist > 0)
        assert net.output("S.ERROR")[0] < 0.1
    finally:
        net.close()


def test_same_seed_same_map(tmp_path):
    maps = []
    for _ in range(2):
        net = load(tmp_path, SOM)
        try:
            net.run(ticks=50)
            maps.append(net.output("S.WEIGHTS").copy())
        finally:
            net.close()
    assert np.array_equal(maps[0], maps[1])


IMAGE = np.arange(30, dtype=float).reshape(5, 6) % 7 / 7


@pytest.mark.parametrize("output_type", ["combined", "separate"])
def test_activity_layout_colours_and_reconstruction(tmp_path, output_type):
    net = load(tmp_path,
               f'<module class="Constant" name="I" data="{matrix_text(IMAGE, ".9g")}"/>'
               '<module class="CSOM" name="S" rf_size_x="3" rf_size_y="2" rf_inc_x="2" '
               'rf_inc_y="1" som_size_x="3" som_size_y="2" use_arbor="no" alpha="0" '
               f'alpha_min="0" output_type="{output_type}" seed="4"/>'
               '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        X, my, mx = fields(IMAGE, 2, 3, 1, 2)
        assert (my, mx) == (4, 2)
        assert net.output("S.OUTPUT").shape == (my * 2, mx * 3)
        assert net.output("S.OUTPUT_RED").shape == (4, 2)
        assert net.output("S.WEIGHTS").shape == (2 * 2, 3 * 3)
        assert net.output("S.RECONSTRUCTION").shape == (5, 6)
        for _ in range(3):
            net.step()
            W = unit_weights(net.output("S.WEIGHTS"), 2, 3, 2, 3).astype(float)
            mse = ((X[:, None, :] - W[None]) ** 2).mean(-1)          # (fields, units)
            act = 1 / (1 + mse)
            a = act.reshape(my, mx, 2, 3)
            if output_type == "combined":
                expected = a.transpose(0, 2, 1, 3).reshape(my * 2, mx * 3)
                assert net.output("S.OUTPUT")[2 * 1 + 1, 3 * 1 + 2] == pytest.approx(
                    act[1 * mx + 1, 1 * 3 + 2], rel=1e-5)
            else:
                expected = a.transpose(2, 0, 3, 1).reshape(2 * my, 3 * mx)
                assert net.output("S.OUTPUT")[1 * my + 2, 2 * mx + 1] == pytest.approx(
                    act[2 * mx + 1, 1 * 3 + 2], rel=1e-5)
            assert np.allclose(net.output("S.OUTPUT"), expected, rtol=1e-5)
            best = mse.argmin(1)
            by, bx = np.divmod(best, 3)
            m = act[np.arange(len(best)), best]
            scale = (m / m.max()).reshape(my, mx)
            assert np.allclose(net.output("S.OUTPUT_RED"), scale * (by / 1).reshape(my, mx))
            assert np.allclose(net.output("S.OUTPUT_GREEN"), scale * (bx / 2).reshape(my, mx))
            assert np.allclose(net.output("S.OUTPUT_BLUE"),
                               scale * (1 - by / 2 - bx / 4).reshape(my, mx))
            assert net.output("S.ERROR")[0] == pytest.approx(
                np.sqrt(mse[np.arange(len(best)), best].mean()), rel=1e-5)
            recon, count = np.zeros((5, 6)), np.zeros((5, 6))
            for p, (j, i) in enumerate((j, i) for j in range(my) for i in range(mx)):
                recon[j:j + 2, 2 * i:2 * i + 3] += W[best[p]].reshape(2, 3)
                count[j:j + 2, 2 * i:2 * i + 3] += 1
            expected_recon = np.divide(recon, count, out=np.zeros_like(recon), where=count > 0)
            assert np.allclose(net.output("S.RECONSTRUCTION"), expected_recon, atol=1e-6)
            assert np.all(net.output("S.RECONSTRUCTION")[:, 5] == 0)   # not covered
        assert net.output("S.PROGRESS")[0] == pytest.approx(0, abs=1e-7)  # no learning
    finally:
        net.close()


def write_state(path, W, extra=()):
    np.savetxt(path, np.concatenate([np.ravel(W), np.ravel(extra)]))


@pytest.mark.parametrize("topology", ["plane", "torus"])
def test_learning_step_matches_numpy(tmp_path, topology):
    rng = np.random.default_rng(0)
    W = rng.random((3 * 4, 2))                        # 3 x 4 map, 1 x 2 fields
    write_state(tmp_path / "start.dat", W)
    x = np.array([0.9, 0.2])
    net = load(tmp_path,
               f'<module class="Constant" name="I" data="{matrix_text(x, ".9g")}"/>'
               '<module class="CSOM" name="S" rf_size_x="2" rf_size_y="1" som_size_x="4" '
               'som_size_y="3" use_arbor="no" alpha="0.5" alpha_max="1" alpha_decay="0.5" '
               'alpha_min="0.1" '
               'sigma="0.4" sigma_decay="0.5" sigma_min="0.1" load_state="yes" '
               f'load_weights_only="yes" filename="start.dat" topology="{topology}"/>'
               '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        assert np.allclose(unit_weights(net.output("S.WEIGHTS"), 3, 4, 1, 2), W)
        gy, gx = np.divmod(np.arange(12), 4)
        alpha, sigma = 0.5, 0.4
        for _ in range(4):
            best = ((W - x) ** 2).sum(1).argmin()
            dy, dx = abs(gy - gy[best]), abs(gx - gx[best])
            if topology == "torus":
                dy, dx = np.minimum(dy, 3 - dy), np.minimum(dx, 4 - dx)
            s = sigma * np.hypot(2, 1.5)
            h = np.exp(-(dy ** 2 + dx ** 2) / (2 * s * s))
            W = W + alpha * h[:, None] * (x - W)
            alpha, sigma = max(alpha * 0.5, 0.1), max(sigma * 0.5, 0.1)
            net.step()
            assert np.allclose(unit_weights(net.output("S.WEIGHTS"), 3, 4, 1, 2), W,
                               atol=1e-6)
    finally:
        net.close()


def test_blocks_and_spans_and_arbor(tmp_path):
    image = np.array([[0.1, 0.5, 0.9, 0.3, 0.7, 0.2, 0.8, 0.4]])
    W = np.array([[0.2, 0.4, 0.6, 0.8], [0.9, 0.1, 0.5, 0.5]])
    write_state(tmp_path / "w.dat", W)
    net = load(tmp_path,
               f'<module class="Constant" name="I" data="{matrix_text(image, ".9g")}"/>'
               '<module class="CSOM" name="S" rf_size_x="4" rf_size_y="1" block_size_x="2" '
               'span_size_x="1" som_size_x="2" som_size_y="1" alpha="0" alpha_min="0" '
               'use_arbor="yes" load_state="yes" filename="w.dat"/>'
               '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        # a field is columns c, c+1, c+3, c+4 (two blocks of 2 with a gap of 1): 4 fields
        X = np.array([image[0, [c, c + 1, c + 3, c + 4]] for c in range(4)])
        assert net.output("S.OUTPUT").shape == (1, 4 * 2)
        x = (np.arange(4) - 1.5) / 2.25                   # the arbor along the field
        arbor = np.maximum(0, 1 - x ** 2)
        net.step()
        mse = ((X[:, None, :] - W[None]) ** 2 @ arbor) / arbor.sum()
        assert np.allclose(net.output("S.OUTPUT").reshape(4, 2), 1 / (1 + mse), rtol=1e-5)
    finally:
        net.close()


def test_state_is_saved_and_loaded(tmp_path):
    net = load(tmp_path, SOM.replace('seed="1"/>', 'seed="1" save_state="yes" '
                                     'filename="map.dat"/>'))
    try:
        net.run(ticks=100)
        saved = net.output("S.WEIGHTS").copy()
    finally:
        net.close()
    assert (tmp_path / "map.dat").exists()
    net = load(tmp_path, SOM.replace('seed="1"/>', 'seed="2" load_state="yes" '
                                     'filename="map.dat" update_weights="no"/>'))
    try:
        assert np.allclose(net.output("S.WEIGHTS"), saved)
        net.run(ticks=5)
        assert np.allclose(net.output("S.WEIGHTS"), saved)      # update_weights off
    finally:
        net.close()


def test_two_streams_share_the_map(tmp_path):
    write_state(tmp_path / "w.dat", [[0.4] * 4, [0.6] * 4])
    net = load(tmp_path,
               '<module class="Constant" name="A" data="0 0 0 0; 0 0 0 0"/>'
               '<module class="Constant" name="B" data="1 1 1 1; 1 1 1 1"/>'
               '<module class="CSOM" name="S" upstreams="2" rf_size_x="2" rf_size_y="2" '
               'rf_inc_x="2" rf_inc_y="2" som_size_x="2" som_size_y="1" use_arbor="no" '
               'alpha="0.5" alpha_max="0.5" sigma="0.01" sigma_min="0.01" load_state="yes" '
               'filename="w.dat"/>'
               '<connection source="A.OUTPUT" target="S.INPUT1" delay="0"/>'
               '<connection source="B.OUTPUT" target="S.INPUT2" delay="0"/>')
    try:
        assert net.output("S.OUTPUT1").shape == net.output("S.OUTPUT2").shape == (1, 4)
        net.run(ticks=60)
        W = unit_weights(net.output("S.WEIGHTS"), 1, 2, 2, 2)
        # unit 0 has learned the fields of stream 1 (all 0), unit 1 those of stream 2 (all 1)
        assert np.allclose(W, [[0] * 4, [1] * 4], atol=1e-4)
        one, two = net.output("S.OUTPUT1").reshape(2, 2), net.output("S.OUTPUT2").reshape(2, 2)
        assert np.allclose(one, [[1, 0.5], [1, 0.5]], atol=1e-3)    # 1 / (1 + mse)
        assert np.allclose(two, [[0.5, 1], [0.5, 1]], atol=1e-3)
        assert np.array_equal(net.output("S.OUTPUT"), net.output("S.OUTPUT1"))
        assert np.array_equal(net.output("S.OUTPUT_GREEN2"), [[1, 1]])
    finally:
        net.close()


def test_unconnected_input_is_an_error(tmp_path):
    with pytest.raises(Exception, match="INPUT"):
        load(tmp_path, '<module class="CSOM" name="S"/>')


def test_learning_buffer_samples_the_fields(tmp_path):
    # all fields alike: learning from 2 sampled fields equals learning from all 6
    weights = []
    for size in (-1, 2):
        net = load(tmp_path,
                   '<module class="Constant" name="I" data="0.5 0.5 0.5 0.5; 0.5 0.5 0.5 0.5"/>'
                   '<module class="CSOM" name="S" rf_size_x="2" rf_size_y="1" som_size_x="2" '
                   'som_size_y="2" use_arbor="no" alpha="0.3" alpha_max="0.3" '
                   f'learning_buffer_size="{size}" seed="6"/>'
                   '<connection source="I.OUTPUT" target="S.INPUT" delay="0"/>')
        try:
            net.run(ticks=5)
            weights.append(net.output("S.WEIGHTS").copy())
        finally:
            net.close()
    assert np.allclose(weights[0], weights[1], atol=1e-6)
    assert not np.allclose(weights[0], 0.005, atol=0.01)          # they did learn
