"""The statistical tests of Statistics (MODULES-V3 §7): one-way ANOVA and Kruskal–Wallis
over channels, Anderson–Darling normality, pairwise Welch and Mann–Whitney tests, and the
adjustment of p-values."""
import math

import numpy as np

from ._special import (f_upper_tail, incomplete_beta, normal_cdf, upper_incomplete_gamma)

NAN = math.nan


def ranks(values: np.ndarray) -> tuple[np.ndarray, float]:
    """Ranks from 1 with ties averaged, and Σ(t³ − t) over the groups of ties."""
    order = np.argsort(values, kind="stable")
    sorted_values = values[order]
    result = np.empty(len(values))
    ties = 0.0
    i = 0
    while i < len(values):
        j = i
        while j + 1 < len(values) and sorted_values[j + 1] == sorted_values[i]:
            j += 1
        result[order[i:j + 1]] = (i + j) / 2 + 1
        t = j - i + 1
        ties += t ** 3 - t
        i = j + 1
    return result, ties


def group_test(groups: list, parametric: bool) -> list:
    """[p, statistic, df1, df2, effect size, groups] over the non-empty channels."""
    groups = [g for g in groups if len(g)]
    G, N = len(groups), sum(len(g) for g in groups)
    if G < 2 or N <= G:
        return [NAN] * 6
    if parametric:
        grand = sum(g.sum() for g in groups) / N
        ssb = sum(len(g) * (g.mean() - grand) ** 2 for g in groups)
        ssw = sum(((g - g.mean()) ** 2).sum() for g in groups)
        msb, msw = ssb / (G - 1), ssw / (N - G)
        f = (0.0 if msb == 0 else math.inf) if msw == 0 else msb / msw
        effect = ssb / (ssb + ssw) if ssb + ssw != 0 else 0.0
        return [f_upper_tail(f, G - 1, N - G), f, G - 1, N - G, effect, G]
    pooled, ties = ranks(np.concatenate(groups))
    h, start = 0.0, 0
    for g in groups:
        h += pooled[start:start + len(g)].sum() ** 2 / len(g)
        start += len(g)
    h = 12 / (N * (N + 1)) * h - 3 * (N + 1)
    factor = 1 - ties / (N ** 3 - N)
    if factor > 0:
        h /= factor
    p = upper_incomplete_gamma((G - 1) / 2, h / 2)
    return [p, h, G - 1, NAN, min(max((h - G + 1) / (N - G), 0.0), 1.0), G]


def anderson_darling(x: np.ndarray) -> list:
    """[A*, p, mean, sd] of one channel, or NaNs (fewer than 3 samples or sd 0)."""
    n = len(x)
    if n < 3:
        return [NAN] * 4
    mean, sd = x.mean(), x.std(ddof=1)
    if not sd > 0:
        return [NAN] * 4
    phi = np.clip([normal_cdf(z) for z in np.sort((x - mean) / sd)], 1e-15, 1 - 1e-15)
    i = np.arange(n)
    a2 = -n - np.sum((2 * i + 1) * (np.log(phi) + np.log(1 - phi[::-1]))) / n
    a = a2 * (1 + 0.75 / n + 2.25 / n ** 2)
    if a < 0:
        p = 1.0
    elif a < 0.2:
        p = 1 - math.exp(-13.436 + 101.14 * a - 223.73 * a * a)
    elif a < 0.34:
        p = 1 - math.exp(-8.318 + 42.796 * a - 59.938 * a * a)
    elif a < 0.6:
        p = math.exp(0.9177 - 4.279 * a - 1.38 * a * a)
    else:
        p = math.exp(1.2937 - 5.709 * a + 0.0186 * a * a)
    return [a, min(max(p, 0.0), 1.0), mean, sd]


def welch(a: np.ndarray, b: np.ndarray) -> float:
    n1, n2 = len(a), len(b)
    if n1 < 2 or n2 < 2:
        return NAN
    se1, se2 = a.var(ddof=1) / n1, b.var(ddof=1) / n2
    if se1 == 0 and se2 == 0:
        return 1.0 if a.mean() == b.mean() else 0.0
    t = abs(a.mean() - b.mean()) / math.sqrt(se1 + se2)
    nu = (se1 + se2) ** 2 / (se1 ** 2 / (n1 - 1) + se2 ** 2 / (n2 - 1))
    return incomplete_beta(nu / (nu + t * t), nu / 2, 0.5)


def mann_whitney(a: np.ndarray, b: np.ndarray) -> float:
    n1, n2 = len(a), len(b)
    if n1 < 1 or n2 < 1:
        return NAN
    pooled, ties = ranks(np.concatenate([a, b]))
    N = n1 + n2
    u = pooled[:n1].sum() - n1 * (n1 + 1) / 2
    mean = n1 * n2 / 2
    variance = n1 * n2 / 12 * ((N + 1) - ties / (N * (N - 1)))
    if variance <= 0:
        return 1.0 if u == mean else 0.0
    z = max(0.0, abs(u - mean) - 0.5) / math.sqrt(variance)
    return math.erfc(z / math.sqrt(2))


def adjust(p: np.ndarray, method: str) -> np.ndarray:
    """The adjusted pairwise p-values: the finite ones of the upper triangle adjusted
    together and mirrored; the diagonal 1; others kept."""
    out = p.copy()
    rows, cols = np.triu_indices(len(p), 1)
    finite = np.isfinite(p[rows, cols])
    rows, cols = rows[finite], cols[finite]
    values = p[rows, cols]
    m = len(values)
    if method == "bonferroni":
        values = np.minimum(1, values * m)
    elif method in ("holm", "bh"):
        order = np.argsort(values, kind="stable")
        adjusted = np.empty(m)
        if method == "holm":
            previous = 0.0
            for r, k in enumerate(order):
                previous = adjusted[k] = max(previous, min(1.0, values[k] * (m - r)))
        else:
            following = 1.0
            for r in range(m - 1, -1, -1):
                k = order[r]
                following = adjusted[k] = min(following, min(1.0, values[k] * m / (r + 1)))
        values = adjusted
    out[rows, cols] = out[cols, rows] = values
    np.fill_diagonal(out, 1)
    return out
