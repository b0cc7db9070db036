"""Tests of M02_Amygdala against the learning rule worked by hand and the timing of E that
the golden files of Ikaros 2 show (golden-v2 M02_Amygdala)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def write(tmp_path, rows):
    text = "S/2 R/1 EO/1\n" + "\n".join(" ".join(map(str, r)) for r in rows) + "\n"
    (tmp_path / "x.txt").write_text(text)


def reference(rows, alpha, delayed=True):
    """E of each tick: from sum A two ticks back and EO one tick back (delayed), or both of
    the same tick (immediate)."""
    v, s_last, sum_last = np.zeros(2), np.zeros(2), 0.0
    out, e_next = [], 0.0
    for s0, s1, r, eo in rows:
        s = np.array([s0, s1], float)
        v = v + alpha * s_last * max(0.0, r - sum_last)
        a = s * v
        if delayed:
            e, e_next = e_next, min(max(sum_last - eo, 0.0), 1.0)
        else:
            e = min(max(a.sum() - eo, 0.0), 1.0)
        out.append((a.copy(), v.copy(), e))
        s_last, sum_last = s, a.sum()
    return out


ROWS = [[1, 0, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0], [0, 0, 1, 0], [1, 1, 0, 0.1],
        [0, 0, 1, 0], [1, 1, 0, 0.5], [1, 0, 3, 0], [0, 0, 5, 0], [1, 0, 0, 2], [1, 1, 0, 0]]


def run(tmp_path, eo=True, alpha=0.3, response="delayed"):
    write(tmp_path, ROWS)
    body = ('<module class="InputFile" name="X" filename="x.txt"/>'
            f'<module class="M02_Amygdala" name="A" alpha="{alpha}" response="{response}"/>'
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


@pytest.mark.parametrize("response", ["delayed", "immediate"])
def test_matches_the_rule(tmp_path, response):
    got = run(tmp_path, response=response)
    for (a, v, e), (ra, rv, re) in zip(got, reference(ROWS, 0.3, response == "delayed")):
        assert np.allclose(a, ra, atol=1e-6) and np.allclose(v, rv, atol=1e-6)
        assert abs(e - re) < 1e-6
    es = [e for _, _, e in got]
    assert any(es) and es != [e for _, _, e in reference(ROWS, 0.3, response != "delayed")]
    # hand-worked: the first pairing gives v0 = 0.3; the next 0.3 + 0.3 * (1 - 0.3) = 0.51
    v_after = [v for _, v, _ in run(tmp_path)]
    assert np.allclose(v_after[1], [0.3, 0]) and np.allclose(v_after[3], [0.51, 0])


def test_weights_of_positive_stimuli_never_decrease_and_are_not_bounded(tmp_path):
    v = np.array([v for _, v, _ in run(tmp_path, alpha=0.9)])
    assert np.all(np.diff(v, axis=0) >= 0)
    # hand-worked: ticks 2 and 4 give 0.9 and 0.9 + 0.9 (1 - 0.9) = 0.99; the reward 3 on
    # tick 7 after S = 1 on tick 6, with sum A = 0.99 + v1: above 1
    assert v[1][0] == pytest.approx(0.9) and v[3][0] == pytest.approx(0.99) and v.max() > 1


def test_unconnected_eo_means_no_inhibition(tmp_path):
    rows = [r[:3] + [0] for r in ROWS]
    for (a, v, e), (ra, rv, re) in zip(run(tmp_path, eo=False), reference(rows, 0.3)):
        assert abs(e - re) < 1e-6


def test_a_and_v_keep_the_shape_of_a_matrix_input(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="S" data="1 0; 0 2"/>'
                         '<module class="Constant" name="R" data="1"/>'
                         '<module class="M02_Amygdala" name="A" alpha="0.5"/>'
                         '<connection source="S.OUTPUT" target="A.INPUT" delay="0"/>'
                         '<connection source="R.OUTPUT" target="A.Rew" delay="0"/>')
    try:
        net.run(ticks=2)
        assert net.output("A.V").shape == net.output("A.A").shape == (2, 2)
        assert np.allclose(net.output("A.V"), [[0.5, 0], [0, 1]])     # 0.5 * S * 1
        assert np.allclose(net.output("A.A"), [[0.5, 0], [0, 2]])
    finally:
        net.close()
