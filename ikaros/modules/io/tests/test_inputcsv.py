"""Tests of the InputCSV module."""
import numpy as np
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.testing import load_body as load

CSV = ("X[1],Y,X[0],M[0][1],M[1][0],M[0][0],M[1][1]\r\n"
       "2,3,1,12,21,11,22\r\n"
       "5,,4,0.5,-1,1e-3,7\r\n"
       "\r\n"
       "8,9,7\r\n")


def csv_body(tmp_path, attributes="", text=CSV, extra=""):
    (tmp_path / "d.csv").write_text(text, newline="")
    return load(tmp_path, f'<module class="InputCSV" name="F" filename="d.csv" '
                          f'{attributes}/>\n{extra}')


def values(net):
    return (net.output("F.X").tolist(), net.output("F.Y").tolist(), net.output("F.M").tolist())


ROWS = [([1, 2], [3], [[11, 12], [21, 22]]),
        ([4, 5], [0], [[1e-3, 0.5], [-1, 7]]),
        ([7, 8], [9], [[0, 0], [0, 0]])]


def expected(k):
    x, y, m = ROWS[k]
    return (np.float32(x).tolist(), np.float32(y).tolist(), np.float32(m).tolist())


def test_columns_grouped_by_name_one_row_per_tick(tmp_path):
    net = csv_body(tmp_path)
    try:
        assert net.output("F.X").shape == (2,)
        assert net.output("F.Y").shape == (1,)
        assert net.output("F.M").shape == (2, 2)
        assert values(net) == ([0, 0], [0], [[0, 0], [0, 0]])       # init
        for k in range(3):
            net.step()
            assert values(net) == expected(k), k
        assert net.tick == 3
        with pytest.raises(RunError, match="end_of_file"):
            net.step()
    finally:
        net.close()


def test_iterations_repetitions_extend(tmp_path):
    net = csv_body(tmp_path, 'iterations="2" repetitions="2" extend="1" '
                             'send_end_of_file="no"')
    try:
        got = []
        for _ in range(14):
            net.step()
            got.append(values(net))
        zeros = ([0, 0], [0], [[0, 0], [0, 0]])
        assert got == [expected(k) for k in (0, 0, 1, 1, 2, 2) * 2] + [zeros] * 2
    finally:
        net.close()
    net = csv_body(tmp_path, 'extend="2"')
    try:
        for _ in range(5):                                         # 3 rows + 2 ticks
            net.step()
        with pytest.raises(RunError, match="end_of_file"):
            net.step()
    finally:
        net.close()


def test_iterations_zero_is_forever(tmp_path):
    net = csv_body(tmp_path, 'iterations="0"')
    try:
        for tick in range(8):
            net.step()
            assert values(net) == expected(tick % 3)
    finally:
        net.close()


def test_semicolon_tab_bom_and_port_names(tmp_path):
    text = "\ufefftime (s);a-b;2x\n0,5;1;2\n"
    with pytest.raises(ModelError, match="is not a number"):
        csv_body(tmp_path, 'delimiter=";"', text=text)    # a decimal comma is not a number
    text = "\ufefftime (s);a-b;2x\n0.5;1;2\n"
    net = csv_body(tmp_path, 'delimiter=";"', text=text)
    try:
        net.step()
        assert net.output("F.time__s_").tolist() == [0.5]
        assert net.output("F.a-b").tolist() == [1]
        assert net.output("F._2x").tolist() == [2]
    finally:
        net.close()
    net = csv_body(tmp_path, 'delimiter="tab"', text="A\tB[0]\tB[1]\n1\t2\t3\n")
    try:
        net.step()
        assert net.output("F.B").tolist() == [2, 3]
    finally:
        net.close()


def test_comma_index_form(tmp_path):
    net = csv_body(tmp_path, text='"M[0,0]","M[0,1]","M[1,0]","M[1,1]"\n1,2,3,4\n')
    try:
        net.step()
        assert net.output("F.M").tolist() == [[1, 2], [3, 4]]
    finally:
        net.close()


@pytest.mark.parametrize("text, message", [
    ("X[0],X[2]\n1,2\n", r"no element X\[1\]"),
    ("X,X\n1,2\n", "appears 2 times"),
    ("X[0],X[0]\n1,2\n", "appears twice"),
    ("X,X[0]\n1,2\n", "different numbers of indices"),
    ("1,2\n3,4\n", "must be a header"),
    ("A,B\n1,2,3\n", "3 values but the header has 2"),
    ("A\nabc\n", '"abc" in column "A" is not a number'),
    ("", "is empty"),
])
def test_bad_files_are_build_errors_with_the_line(tmp_path, text, message):
    with pytest.raises(ModelError, match=message):
        csv_body(tmp_path, text=text)


def test_missing_file_is_a_build_error(tmp_path):
    with pytest.raises(ModelError, match="nothere.csv"):
        load(tmp_path, '<module class="InputCSV" name="F" filename="nothere.csv"/>')
