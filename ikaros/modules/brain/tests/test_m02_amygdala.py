"""Tests of M02_Amygdala against the learning rule worked by hand."""
import numpy as np

from ikaros.testing import load_body as load


def write(tmp_path, rows):
    text = "S/2 R/1 EO/1\n" + "\n".join(" ".join(map(str, r)) for r in rows) + "\n"
    (tmp_path / "x.txt").write_text(text)


def reference(rows, alpha):
    v, s_last, sum_last = np.zeros(2), np.zeros(2), 0.0
    out = []
    for s0, s1, r, eo in rows:
        s = np.array([s0, s1], float)
        v = np.minimum(v + alpha * s_last * max(0.0, r - sum_last), 1.0)
        a = s * v
        out.append((a.copy(), v.copy(), min(max(a.sum() - eo, 0.0), 1.0)))
        s_last, sum_last = s, a.sum()
    return out


ROWS = [[1, 0, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0], [0, 0, 1, 0], [1, 1, 0, 0.1],
        [0, 0, 1, 0], [1, 1, 0, 0.5], [1, 0, 3, 0], [0, 0, 5, 0], [1, 0, 0, 2], [1, 1, 0, 0]]


def run(tmp_path, eo=True, alpha=0.3):
    write(tmp_path, ROWS)
    body = ('<module class="InputFile" name="X" filename="x.txt"/>'
            f'<module class="M02_Amygdala" name="A" alpha="{alpha}"/>'
            '<connection source="X.S" target="A.INPUT" delay="0"/>'
            '<connection source="X.R" target="A.Rew" delay="0"/>')
    if eo:
        body += '<connection source="X.EO" target="A.EO" delay="0"/>'
    net = load(tmp_path, body)
    try:
        got = []
        for _ in ROWS:
            net.step()
            got.append((net.output("A.A").copy(), net.output("A.V").copy(),
                        float(net.output("A.E")[0])))
        return got
    finally:
        net.close()


def test_matches_the_rule(tmp_path):
    rows = [r[:3] + [r[3]] for r in ROWS]
    for (a, v, e), (ra, rv, re) in zip(run(tmp_path), reference(rows, 0.3)):
        assert np.allclose(a, ra, atol=1e-6) and np.allclose(v, rv, atol=1e-6)
        assert abs(e - re) < 1e-6
    # hand-worked: the first pairing gives v0 = 0.3; the next 0.3 + 0.3 * (1 - 0.3) = 0.51
    v_after = [v for _, v, _ in run(tmp_path)]
    assert np.allclose(v_after[1], [0.3, 0]) and np.allclose(v_after[3], [0.51, 0])


def test_weights_never_decrease_and_stay_at_most_1(tmp_path):
    v = np.array([v for _, v, _ in run(tmp_path, alpha=0.9)])
    assert np.all(np.diff(v, axis=0) >= 0) and v.max() <= 1 and v.max() == 1


def test_unconnected_eo_means_no_inhibition(tmp_path):
    rows = [r[:3] + [0] for r in ROWS]
    for (a, v, e), (ra, rv, re) in zip(run(tmp_path, eo=False), reference(rows, 0.3)):
        assert abs(e - re) < 1e-6
