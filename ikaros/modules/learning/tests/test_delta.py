"""Tests of the Delta module: the delta rule, acquisition only."""
import numpy as np
import pytest

from ikaros.testing import load_body


def data_file(tmp_path, header, rows):
    lines = [header] + [" ".join(f"{v:.6g}" for v in row) for row in rows]
    (tmp_path / "data.txt").write_text("\n".join(lines) + "\n")


def run(net, ticks, path):
    got = []
    for _ in range(ticks):
        net.step()
        got.append(net.output(path).copy())
    return np.array(got)


def test_single_stimulus_follows_the_delta_rule(tmp_path):
    # CS = (1, 0.5), sum(US) = 1: CR_n = 1 - (1 - alpha |CS|^2)^n = 1 - 0.875^n
    net = load_body(tmp_path, '<module class="Constant" name="CS" data="1 0.5"/>'
                    '<module class="Constant" name="US" data="0.6 0.4"/>'
                    '<module class="Delta" name="D" alpha="0.1"/>'
                    '<connection source="CS.OUTPUT" target="D.CS" delay="0"/>'
                    '<connection source="US.OUTPUT" target="D.US" delay="0"/>')
    try:
        assert net.output("D.CR").shape == (1,)
        cr = run(net, 30, "D.CR")[:, 0]
        np.testing.assert_allclose(cr, 1 - 0.875 ** np.arange(30), rtol=1e-5, atol=1e-6)
    finally:
        net.close()


def test_learns_a_linear_map_and_predicts_held_out_compounds(tmp_path):
    w_true = np.array([0.5, 1.5, 2.0, 0.25])
    rng = np.random.default_rng(3)
    train = [(np.eye(4)[i % 4], w_true[i % 4]) for i in range(200)]
    test_x = rng.random((20, 4))
    # held-out compound stimuli with US = 0: no learning (acquisition only), CR = w . CS
    rows = [list(x) + [y] for x, y in train] + [list(x) + [0.0] for x in test_x]
    data_file(tmp_path, "CS/4 US/1", rows)
    net = load_body(tmp_path, '<module class="InputFile" name="F" filename="data.txt"/>'
                    '<module class="Delta" name="D" alpha="0.2"/>'
                    '<connection source="F.CS" target="D.CS" delay="0"/>'
                    '<connection source="F.US" target="D.US" delay="0"/>')
    try:
        cr = run(net, len(rows), "D.CR")[:, 0]
        # one-hot stimulus i: error shrinks by (1 - alpha) each presentation
        n_seen = np.arange(200) // 4
        expected_train = w_true[np.arange(200) % 4] * (1 - 0.8 ** n_seen)
        np.testing.assert_allclose(cr[:200], expected_train, rtol=1e-4, atol=1e-6)
        np.testing.assert_allclose(cr[200:], test_x @ w_true, rtol=1e-4, atol=1e-4)
    finally:
        net.close()


def test_acquisition_only_and_inverse_output(tmp_path):
    # US = 1 for 40 ticks, then 0: the weights never shrink; output=error gives US - CR
    rows = [[1, 1]] * 40 + [[1, 0]] * 10
    data_file(tmp_path, "CS/1 US/1", rows)
    net = load_body(tmp_path, '<module class="InputFile" name="F" filename="data.txt"/>'
                    '<module class="Delta" name="D" alpha="0.5"/>'
                    '<module class="Delta" name="I" alpha="0.5" output="error"/>'
                    '<connection source="F.CS" target="D.CS" delay="0"/>'
                    '<connection source="F.US" target="D.US" delay="0"/>'
                    '<connection source="F.CS" target="I.CS" delay="0"/>'
                    '<connection source="F.US" target="I.US" delay="0"/>')
    try:
        got_d, got_i = [], []
        for _ in range(len(rows)):
            net.step()
            got_d.append(net.output("D.CR")[0])
            got_i.append(net.output("I.CR")[0])
        cr = 1 - 0.5 ** np.arange(40)
        np.testing.assert_allclose(got_d[:40], cr, atol=1e-6)
        np.testing.assert_allclose(got_d[40:], 1 - 0.5 ** 40, atol=1e-6)   # no extinction
        us = np.array([r[1] for r in rows])
        np.testing.assert_allclose(got_i, us - np.array(got_d), atol=1e-6)
    finally:
        net.close()


def test_unconnected_us_learns_nothing(tmp_path):
    net = load_body(tmp_path, '<module class="Constant" name="CS" data="1 1"/>'
                    '<module class="Delta" name="D"/>'
                    '<module class="Delta" name="E"/>'
                    '<connection source="CS.OUTPUT" target="D.CS" delay="0"/>')
    try:
        assert np.array_equal(run(net, 5, "D.CR"), np.zeros((5, 1)))
        assert np.array_equal(run(net, 2, "E.CR"), np.zeros((2, 1)))
    finally:
        net.close()


@pytest.mark.parametrize("dialect, expected", [("3", [0, 0, 0]), ("2", [0, 0.25, 0.375])])
def test_inverse_in_ikaros_3_and_2_files(tmp_path, dialect, expected):
    # Ikaros 3 (golden Delta.json case "inverse"): with inverse="yes" CR stays 0 while the
    # US exceeds the prediction; Ikaros 2 (golden-v2 case "inverse") ignores inverse: CR
    # grows by alpha (US - CR) per tick
    net = load_body(tmp_path, '<module class="Constant" name="CS" data="1"/>'
                    '<module class="Constant" name="US" data="0.5"/>'
                    '<module class="Delta" name="D" alpha="0.5" inverse="yes"/>'
                    '<connection source="CS.OUTPUT" target="D.CS" delay="0"/>'
                    '<connection source="US.OUTPUT" target="D.US" delay="0"/>',
                    dialect=dialect)
    try:
        got = []
        for _ in range(3):
            net.step()
            got.append(float(net.output("D.CR")[0]))
        assert got == expected
    finally:
        net.close()
