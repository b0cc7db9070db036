"""Tests of the KNN_Pick module, with hand-worked tables."""
import numpy as np
import pytest

from ikaros.testing import load_body


def pick(tmp_path, outputs, distances, attrs=""):
    net = load_body(tmp_path, f'<module class="Constant" name="O" data="{outputs}"/>'
                    f'<module class="Constant" name="D" data="{distances}"/>'
                    f'<module class="KNN_Pick" name="P" {attrs}/>'
                    '<connection source="O.OUTPUT" target="P.OUTPUT_TABLE" delay="0"/>'
                    '<connection source="D.OUTPUT" target="P.DISTANCE_TABLE" delay="0"/>')
    try:
        got = []
        for _ in range(3):                       # the same answer on every tick
            net.step()
            got.append(net.output("P.CLASS_OUTPUT"))
        assert all(np.array_equal(g, got[0]) for g in got)
        return got[0]
    finally:
        net.close()


def test_majority_vote(tmp_path):
    # class 2 has three members, class 1 two (one nearer): the majority wins
    out = pick(tmp_path, "1 2 2 1 2", "0.1 0.5 0.6 0.7 0.9")
    assert out.shape == (1,) and out[0] == 2


def test_tie_goes_to_the_class_listed_last(tmp_path):
    # golden-v2 KNN_Pick "vector": four classes of one member each give the last
    assert pick(tmp_path, "1 2 2 1", "0.4 0.3 0.9 0.5")[0] == 1
    assert pick(tmp_path, "1 2 1 2", "0.2 0.3 0.9 0.5")[0] == 2
    assert pick(tmp_path, "3 1 2", "0.2 0.3 0.1")[0] == 2


def test_weighed_vote(tmp_path):
    # weights 1/ln(1.0001 + d): one neighbour at 0.05 outweighs two at 2.0
    w = 1 / np.log(1.0001 + np.array([0.05, 2.0, 2.0]))
    assert w[0] > w[1] + w[2]
    assert pick(tmp_path, "3 4 4", "0.05 2 2")[0] == 4
    assert pick(tmp_path, "3 4 4", "0.05 2 2", 'weighed="yes"')[0] == 3


def test_mean_plain_and_weighed(tmp_path):
    out = pick(tmp_path, "1 2 6", "1 2 3", 'categorical="no"')
    np.testing.assert_allclose(out, [3.0])
    w = 2.5 / np.log(1.0001 + np.array([1.0, 2.0, 3.0]))
    out = pick(tmp_path, "1 2 6", "1 2 3", 'categorical="no" weighed="yes" '
               'weight_divisor="2.5"')
    np.testing.assert_allclose(out, [w @ [1, 2, 6] / w.sum()], rtol=1e-6)


def test_a_neighbour_at_distance_0_is_one_vote(tmp_path):
    # golden-v2 KNN_Pick "matrix": a class at distance 0 does not win by itself
    assert pick(tmp_path, "1 1 1 9", "0.5 0.2 0.3 0")[0] == 1
    np.testing.assert_allclose(pick(tmp_path, "1 1 1 9", "0.5 0.2 0.3 0",
                                    'categorical="no"'), [3])


def test_missing_neighbours_count_unless_skipped(tmp_path):
    # Ikaros 2 counts neighbours of negative distance (golden-v2 KNN_Pick "varying")
    assert pick(tmp_path, "4 0 0", "0.5 -1 -1")[0] == 0
    np.testing.assert_allclose(pick(tmp_path, "4 2 0", "0.5 1 -1", 'categorical="no"'), [2])
    assert pick(tmp_path, "4 0 0", "0.5 -1 -1", 'skip_missing="yes"')[0] == 4
    np.testing.assert_allclose(pick(tmp_path, "4 2 0", "0.5 1 -1",
                                    'categorical="no" skip_missing="yes"'), [3])
    assert pick(tmp_path, "4 2 0", "-1 -1 -1", 'skip_missing="yes"')[0] == 0


def test_one_class_per_distance_whatever_the_shape(tmp_path):
    # golden-v2 KNN_Pick "matrix": a 2 x 3 table with six distances is six classes
    out = pick(tmp_path, "5 6 7; 5 8 9", "1 2 3 4 5 6")
    assert out.shape == (1,) and out[0] == 5


def test_rows_of_several_elements(tmp_path):
    # each row is one class vector: (1, 0) twice beats (0, 1) once
    out = pick(tmp_path, "0 1; 1 0; 1 0", "0.1 0.2 0.3")
    np.testing.assert_array_equal(out, [1, 0])
    out = pick(tmp_path, "0 1; 1 0; 1 0", "0.1 0.2 0.3", 'categorical="no"')
    np.testing.assert_allclose(out, [2 / 3, 1 / 3], rtol=1e-6)


def test_weight_divisor_zero_gives_zero_and_a_warning(tmp_path, capsys):
    out = pick(tmp_path, "1 2", "1 2", 'categorical="no" weighed="yes" weight_divisor="0"')
    assert out[0] == 0
    captured = capsys.readouterr()
    assert (captured.out + captured.err).count("weights sum to 0") == 1


def test_mismatched_tables_are_a_build_error(tmp_path):
    with pytest.raises(Exception, match="DISTANCE_TABLE"):
        pick(tmp_path, "1 2 3", "1 2")
