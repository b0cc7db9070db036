"""Tests of the Statistics module (Ikaros 3, MODULES-V3 §7), against formulas computed here
with NumPy (and numerical integration for the distributions)."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load

ROWS = [[1.0, 4.0, 10.0], [2.0, 4.5, 11.0], [2.0, 6.0, 9.5], [3.5, 5.0, 30.0],
        [2.5, 7.0, 10.5], [1.5, 4.0, 9.0], [2.0, 5.5, 10.0], [3.0, 6.5, 11.5]]


def _run(tmp_path, attrs="", rows=ROWS, sample=None):
    lines = ["X/3" + (" S/3" if sample else "")]
    for k, row in enumerate(rows):
        lines.append(" ".join(str(v) for v in row + (sample[k] if sample else [])))
    (tmp_path / "x.txt").write_text("\n".join(lines) + "\n")
    body = ('<module class="InputFile" name="F" filename="x.txt"/>'
            f'<module class="Statistics" name="S" {attrs}/>'
            '<connection source="F.X" target="S.INPUT" delay="0"/>')
    if sample:
        body += '<connection source="F.S" target="S.SAMPLE" delay="0"/>'
    net = load(tmp_path, body)
    try:
        for _ in rows:
            net.step()
        return {s.name: net.output(f"S.{s.name}").copy() for s in net.ports("S")[1]}
    finally:
        net.close()


def t_upper_two_sided(t, nu):
    """2 P(T > t) for Student's t, by integrating its density."""
    x = np.linspace(t, t + 400, 400001)
    pdf = math.gamma((nu + 1) / 2) / (math.sqrt(nu * math.pi) * math.gamma(nu / 2)) * \
        (1 + x * x / nu) ** (-(nu + 1) / 2)
    return 2 * np.trapezoid(pdf, x)


def test_descriptive_statistics_and_box_plot(tmp_path):
    out = _run(tmp_path, 'bins="5"')
    x = np.array(ROWS)
    n = len(x)
    m = x.mean(axis=0)
    dev = x - m
    s2 = (dev ** 2).sum(0) / (n - 1)
    skew = n * (dev ** 3).sum(0) / ((n - 1) * (n - 2) * s2 ** 1.5)
    kurt = (n * (n + 1) / (n - 1) * (dev ** 4).sum(0) / s2 ** 2 - 3 * (n - 1) ** 2) / \
        ((n - 2) * (n - 3))
    q1, med, q3 = np.percentile(x, [25, 50, 75], axis=0)
    assert np.allclose(out["COUNT"], n) and np.allclose(out["MEAN"], m)
    assert np.allclose(out["MEDIAN"], med) and np.allclose(out["Q1"], q1)
    assert np.allclose(out["VARIANCE"], s2) and np.allclose(out["SKEWNESS"], skew, rtol=1e-5)
    assert np.allclose(out["KURTOSIS"], kurt, rtol=1e-5)
    assert out["MODE"].tolist() == [2, 4, 10]
    assert np.allclose(out["OUTPUT"][6], s2) and out["OUTPUT"].shape == (10, 3)
    # channel 2: 30 is an outlier; the upper whisker is the largest sample within the fence
    iqr = q3[2] - q1[2]
    assert np.allclose(out["BOX_PLOT"][:, 2], [q1[2] - 1.5 * iqr, 9, q1[2], med[2], q3[2],
                                               11.5, q3[2] + 1.5 * iqr])
    assert out["BOX_PLOT_OUTLIERS"][0, 2] == 30 and np.isnan(out["BOX_PLOT_OUTLIERS"][1, 2])
    assert np.isnan(out["BOX_PLOT_OUTLIERS"][:, 0]).all()
    # histogram over 1 ... 30 in 5 bins of 5.8
    edges = np.floor((x - 1) / 29 * 5).clip(0, 4).astype(int)
    for i in range(3):
        assert out["HISTOGRAM"][i].tolist() == np.bincount(edges[:, i], minlength=5).tolist()
    assert out["HISTOGRAM_MIN"][0] == 1 and out["HISTOGRAM_MAX"][0] == 30


def test_anova_welch_and_holm(tmp_path):
    out = _run(tmp_path)
    x = np.array(ROWS).T
    n = 8
    grand = x.mean()
    ssb = sum(n * (g.mean() - grand) ** 2 for g in x)
    ssw = sum(((g - g.mean()) ** 2).sum() for g in x)
    f = (ssb / 2) / (ssw / 21)
    # P(F > f) with (2, 21) degrees of freedom, integrated numerically
    v = np.linspace(f, f + 2000, 2000001)
    pdf = math.gamma(23 / 2) / (math.gamma(1) * math.gamma(21 / 2)) * (2 / 21) * \
        (1 + 2 * v / 21) ** (-23 / 2)
    assert np.allclose(out["GROUP_TEST"].ravel(),
                       [np.trapezoid(pdf, v), f, 2, 21, ssb / (ssb + ssw), 3], rtol=1e-4)
    p = np.ones((3, 3))
    for i in range(3):
        for j in range(i + 1, 3):
            a, b = x[i], x[j]
            se = a.var(ddof=1) / n + b.var(ddof=1) / n
            t = abs(a.mean() - b.mean()) / math.sqrt(se)
            nu = se ** 2 / ((a.var(ddof=1) / n) ** 2 / 7 + (b.var(ddof=1) / n) ** 2 / 7)
            p[i, j] = p[j, i] = t_upper_two_sided(t, nu)
    assert np.allclose(out["PAIRWISE_TEST_P"], p, rtol=1e-4, atol=1e-9)
    upper = [p[0, 1], p[0, 2], p[1, 2]]
    order = np.argsort(upper)
    holm, previous = [0.0] * 3, 0.0
    for r, k in enumerate(order):
        previous = holm[k] = max(previous, min(1, upper[k] * (3 - r)))
    assert np.allclose(out["PAIRWISE_TEST_P_ADJUSTED"][[0, 0, 1], [1, 2, 2]], holm,
                       rtol=1e-4)


def test_kruskal_wallis_and_mann_whitney(tmp_path):
    out = _run(tmp_path, 'group_test="non_parametric" pairwise_test="non_parametric" '
                         'p_adjustment="bonferroni"')
    x = np.array(ROWS).T
    pooled = np.concatenate(x)
    rank = np.array([(pooled < v).sum() + ((pooled == v).sum() + 1) / 2 for v in pooled])
    _, counts = np.unique(pooled, return_counts=True)
    ties = (counts ** 3 - counts).sum()
    h = 12 / (24 * 25) * sum(rank[8 * g:8 * g + 8].sum() ** 2 / 8 for g in range(3)) - 75
    h /= 1 - ties / (24 ** 3 - 24)
    # χ² with 2 degrees of freedom: P(X > h) = e^(-h/2)
    assert np.allclose(out["GROUP_TEST"].ravel()[:3], [math.exp(-h / 2), h, 2])
    assert np.isnan(out["GROUP_TEST"][3, 0])
    a, b = x[0], x[1]
    u = sum((ai > bi) + 0.5 * (ai == bi) for ai in a for bi in b)
    both = np.concatenate([a, b])
    _, c = np.unique(both, return_counts=True)
    sigma = math.sqrt(64 / 12 * (17 - (c ** 3 - c).sum() / (16 * 15)))
    p01 = math.erfc(max(0, abs(u - 32) - 0.5) / sigma / math.sqrt(2))
    assert out["PAIRWISE_TEST_P"][0, 1] == pytest.approx(p01, rel=1e-6)
    assert out["PAIRWISE_TEST_P_ADJUSTED"][0, 1] == pytest.approx(min(1, 3 * p01), rel=1e-6)


def test_anderson_darling_and_sampling(tmp_path):
    sample = [[1, 1, 0]] * 4 + [[1, 0, 0]] * 4
    out = _run(tmp_path, sample=sample)
    assert out["COUNT"].tolist() == [8, 4, 0] and np.isnan(out["MEAN"][2])
    x = np.array(ROWS)[:, 0]
    z = np.sort((x - x.mean()) / x.std(ddof=1))
    phi = np.clip([0.5 * math.erfc(-v / math.sqrt(2)) for v in z], 1e-15, 1 - 1e-15)
    i = np.arange(8)
    a = (-8 - np.sum((2 * i + 1) * (np.log(phi) + np.log(1 - phi[::-1]))) / 8) * \
        (1 + 0.75 / 8 + 2.25 / 64)
    assert 0.2 <= a < 0.34           # the second piece of the p approximation
    p = 1 - math.exp(-8.318 + 42.796 * a - 59.938 * a * a)
    assert np.allclose(out["NORMALITY_TEST"][:, 0], [a, p, x.mean(), x.std(ddof=1)])
    assert np.isnan(out["NORMALITY_TEST"][:, 2]).all()
