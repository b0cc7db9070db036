"""Tests of the Maxima module."""

import numpy as np

from ikaros.testing import load_body as load

MATRIX = ("0 0 0 0 0 0; "
          "0 5 1 0 2 0; "
          "0 1 1 0 0 0; "
          "0 0 0 7 0 0; "
          "0 3 0 0 0 9")          # 9 on the border is not a maximum


def run(tmp_path, data, attrs="", ticks=2):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="Maxima" name="M" {attrs}/>'
                         '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.run(ticks=ticks)
        return (net.output("M.OUTPUT"), net.output("M.POINTS"),
                net.output("M.POINT_COUNT"))
    finally:
        net.close()


def brute_force(m, threshold):
    """Interior elements >= threshold and >= all 8 neighbours, in row-major order."""
    rows, cols = m.shape
    found = []
    for j in range(1, rows - 1):
        for i in range(1, cols - 1):
            v = m[j, i]
            if v >= threshold and v >= m[j - 1:j + 2, i - 1:i + 2].max():
                found.append(((i + 0.5) / cols, (j + 0.5) / rows, v))
    return found


def test_hand_worked(tmp_path):
    out, points, count = run(tmp_path, MATRIX, 'threshold="0.5"')
    assert out.shape == (5, 6) and points.shape == (10, 3) and count.shape == (1,)
    expected = np.zeros((5, 6))
    expected[1, 1] = expected[1, 4] = expected[3, 3] = 1
    assert np.array_equal(out, expected)
    assert count[0] == 3
    assert np.allclose(points[:3], [[1.5 / 6, 1.5 / 5, 5], [4.5 / 6, 1.5 / 5, 2],
                                    [3.5 / 6, 3.5 / 5, 7]])
    assert np.all(points[3:] == 0)


def test_threshold_and_plateaus(tmp_path):
    out, _, count = run(tmp_path, MATRIX, 'threshold="4"')
    assert count[0] == 2 and out.sum() == 2
    # a flat input: every interior element is a (non-strict) maximum at threshold 0
    out, _, count = run(tmp_path, "1 1 1; 1 1 1; 1 1 1")
    assert count[0] == 1 and out[1, 1] == 1


def test_sorted_lists_the_largest_first_and_max_points_limits(tmp_path):
    out, points, count = run(tmp_path, MATRIX, 'threshold="0.5" sort_points="yes" '
                                               'max_points="2"')
    assert points.shape == (2, 3) and count[0] == 2
    assert np.allclose(points[:, 2], [7, 5])
    assert out.sum() == 3                       # OUTPUT marks every maximum
    _, points, count = run(tmp_path, MATRIX, 'threshold="0.5" max_points="2"')
    assert np.allclose(points[:, 2], [5, 2])    # unsorted: the first ones, row by row


def test_one_dimensional_input(tmp_path):
    out, points, count = run(tmp_path, "0 3 1 4 4 0 2", 'threshold="0.5"')
    assert count[0] == 0 and np.all(out == 0)        # Ikaros 2: one row, all border
    out, points, count = run(tmp_path, "0 3 1 4 4 0 2", 'threshold="0.5" vectors="along"')
    assert np.array_equal(out, [0, 1, 0, 1, 1, 0, 0])
    assert count[0] == 3
    assert np.allclose(points[0], [1.5 / 7, 0.5, 3])


def test_too_small_input_has_no_maxima(tmp_path):
    out, points, count = run(tmp_path, "5 1; 1 2")
    assert count[0] == 0 and np.all(out == 0) and np.all(points == 0)


def test_random_input_matches_brute_force(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="9" outputsize_y="7" '
                         'seed="11"/>'
                         '<module class="Maxima" name="M" threshold="0.3" max_points="50"/>'
                         '<connection source="R.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            found = brute_force(net.output("R.OUTPUT"), 0.3)
            n = len(found)
            assert net.output("M.POINT_COUNT")[0] == n
            assert np.allclose(net.output("M.POINTS")[:n], found)
            assert net.output("M.OUTPUT").sum() == n
    finally:
        net.close()
