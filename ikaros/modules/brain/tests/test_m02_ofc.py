"""Tests of M02_OFC against its learning rule."""
import numpy as np

from ikaros.testing import load_body as load


def reference(rows, beta, n_con):
    n = 2 * n_con
    w, t_last, sum_o_last = np.zeros(n), np.zeros(n), 0.0
    out = []
    for s0, s1, a, r, *con in rows:
        s = np.array([s0, s1], float)
        t = np.outer(con, s).ravel() if n_con > 1 else s
        if r != 0:
            rr = max(0.0, a - r) - sum_o_last
        else:
            rr = max(0.0, a - sum_o_last)
        w = np.clip(w + beta * t_last * rr, 0, 1)
        o = t * w
        out.append((w.copy(), o.sum()))
        t_last, sum_o_last = t, o.sum()
    return out


def run(tmp_path, rows, beta, con):
    header = "S/2 A/1 R/1" + (" C/2" if con else "")
    (tmp_path / "x.txt").write_text(header + "\n" + "\n".join(
        " ".join(map(str, r)) for r in rows) + "\n")
    body = ('<module class="InputFile" name="X" filename="x.txt"/>'
            f'<module class="M02_OFC" name="O" beta="{beta}"/>'
            '<connection source="X.S" target="O.INPUT" delay="0"/>'
            '<connection source="X.A" target="O.A" delay="0"/>'
            '<connection source="X.R" target="O.Rew" delay="0"/>')
    if con:
        body += '<connection source="X.C" target="O.CON" delay="0"/>'
    net = load(tmp_path, body)
    try:
        assert net.output("O.W").shape == ((4,) if con else (2,))
        got = []
        for _ in rows:
            net.step()
            got.append((net.output("O.W").copy(), float(net.output("O.EO")[0])))
        return got
    finally:
        net.close()


def test_extinction_builds_inhibition_and_reward_removes_it(tmp_path):
    # CS alone followed by a prediction of 1 and no reward, 5 times; then rewarded
    rows = [[1, 0, 0, 0], [0, 0, 1, 0]] * 5 + [[1, 0, 0, 0], [0, 0, 1, 1]] * 5
    got = run(tmp_path, rows, 0.5, con=False)
    for (w, eo), (rw, reo) in zip(got, reference(rows, 0.5, 1)):
        assert np.allclose(w, rw, atol=1e-6) and abs(eo - reo) < 1e-6
    w = np.array([g[0][0] for g in got])
    # hand-worked: the gap 1 - w halves on every unrewarded pairing: 0.5, 0.75, 0.875 ...
    assert np.allclose(w[1:10:2], 1 - 0.5 ** np.arange(1, 6))
    # then each rewarded pairing removes beta * EO: w *= 0.5 (EO of the CS tick is w)
    assert np.allclose(w[11::2], w[9] * 0.5 ** np.arange(1, 6))


def test_context_units_learn_separately(tmp_path):
    rows = [[1, 0, 0, 0, 1, 0], [0, 0, 1, 0, 1, 0], [0, 1, 0, 0, 0, 1], [0, 0, 0.5, 0, 0, 1],
            [1, 1, 0, 0, 1, 1], [0, 0, 2, 1, 0, 1], [1, 0, 0, 0, 0, 1]]
    got = run(tmp_path, rows, 0.4, con=True)
    for (w, eo), (rw, reo) in zip(got, reference(rows, 0.4, 2)):
        assert np.allclose(w, rw, atol=1e-6) and abs(eo - reo) < 1e-6
    assert got[1][0][0] > 0 and got[1][0][1:].sum() == 0      # only (CS 0, context 0)
