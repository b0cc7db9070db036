"""Tests of the OutputCSV module."""
import csv

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

BODY = ('<module class="Sweep" name="S" outputsize_x="3" outputsize_y="2" min="0" max="1" '
        'step="0.25"/>\n'
        '<module class="Constant" name="C" data="7"/>\n'
        '<module class="Constant" name="V" data="1.5 -2"/>\n'
        '<module class="OutputCSV" name="O" filename="o.csv" {attrs}>\n'
        '  <column name="M" decimals="2"/><column name="C"/><column name="V" decimals="0"/>\n'
        '</module>\n'
        '<connection source="S.OUTPUT" target="O.M" delay="0"/>\n'
        '<connection source="C.OUTPUT" target="O.C" delay="0"/>\n'
        '<connection source="V.OUTPUT" target="O.V" delay="0"/>\n')


def read_rows(path, delimiter=","):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.reader(f, delimiter=delimiter))


def test_header_names_and_one_row_per_tick(tmp_path):
    net = load(tmp_path, BODY.format(attrs=""))
    try:
        net.run(ticks=3)
    finally:
        net.close()
    rows = read_rows(tmp_path / "o.csv")
    assert rows[0] == ["T", "M[0][0]", "M[0][1]", "M[0][2]", "M[1][0]", "M[1][1]", "M[1][2]",
                       "C", "V[0]", "V[1]"]
    assert len(rows) == 4
    for tick, row in enumerate(rows[1:]):
        m = f"{0.25 * (tick + 1):.2f}"
        assert row == [str(tick)] + [m] * 6 + ["7.0000", "2", "-2"]   # %.0f rounds 1.5 to 2
    assert (tmp_path / "o.csv").read_bytes().count(b"\r\n") == 4   # RFC 4180 line ends


def test_round_trip_through_inputcsv(tmp_path):
    net = load(tmp_path, BODY.format(attrs='timestamp="no" decimals="6" delimiter=";"'))
    try:
        net.run(ticks=2)
    finally:
        net.close()
    assert read_rows(tmp_path / "o.csv", ";")[0][0] == "M[0][0]"
    net = load(tmp_path, '<module class="InputCSV" name="I" filename="o.csv" '
                         'delimiter=";"/>')
    try:
        assert net.output("I.M").shape == (2, 3)
        net.step()
        assert np.allclose(net.output("I.M"), 0.25)
        assert net.output("I.C").tolist() == [7]
        assert net.output("I.V").tolist() == [2, -2]
        net.step()
        assert np.allclose(net.output("I.M"), 0.5)
    finally:
        net.close()


def test_write_gate(tmp_path):
    (tmp_path / "w.txt").write_text("W/1\n1\n0\n1\n")
    net = load(tmp_path, '<module class="InputFile" name="W" filename="w.txt"/>\n'
                         '<module class="Constant" name="C" data="3"/>\n'
                         '<module class="OutputCSV" name="O" filename="o.csv">'
                         '<column name="X"/></module>\n'
                         '<connection source="C.OUTPUT" target="O.X" delay="0"/>\n'
                         '<connection source="W.W" target="O.WRITE" delay="0"/>')
    try:
        net.run(ticks=3)
    finally:
        net.close()
    assert read_rows(tmp_path / "o.csv") == [["T", "X"], ["0", "3.0000"], ["2", "3.0000"]]


def test_column_errors(tmp_path):
    with pytest.raises(ModelError, match="at least one"):
        load(tmp_path, '<module class="OutputCSV" name="O"/>')
    with pytest.raises(ModelError, match="used twice"):
        load(tmp_path, '<module class="OutputCSV" name="O"><column name="A"/>'
                       '<column name="A"/></module>')
