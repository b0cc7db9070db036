"""Tests of the OutputFile module."""
import json
import shutil
from xml.sax.saxutils import quoteattr
from pathlib import Path

import numpy as np
import pytest

import ikaros
from ikaros.errors import ModelError
from ikaros.module import WARNING

EXAMPLE = Path(__file__).resolve().parents[4] / "examples" / "modules" / "OutputFile_example.ikg"

# Sweep 0..100 step 1: 1, 2, 3, ... on ticks 0, 1, 2, ...
SOURCES = ('<module class="Sweep" name="W" min="0" max="100" step="1"/>\n'
           '<module class="Constant" name="C" data="1.5 -2.25"/>\n'
           '<connection source="W.OUTPUT" target="O.A" delay="0"/>\n'
           '<connection source="C.OUTPUT" target="O.B" delay="0"/>\n')
COLUMNS = '<column name="A"/><column name="B" decimals="2"/>'


def run(tmp_path, attributes, extra="", ticks=3, columns=COLUMNS, **overrides):
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">\n{SOURCES}{extra}'
                    f'<module class="OutputFile" name="O" {attributes}>{columns}</module>\n'
                    '</group>\n')
    net = ikaros.load(str(path), **overrides)
    try:
        net.run(ticks=ticks)
    finally:
        net.close()


def test_writes_header_and_one_line_per_tick(tmp_path):
    run(tmp_path, 'filename="out.txt"')
    assert (tmp_path / "out.txt").read_text() == (
        "T/1\tA/1\tB/2\n"
        "0\t1.0000\t1.50\t-2.25\n"
        "1\t2.0000\t1.50\t-2.25\n"
        "2\t3.0000\t1.50\t-2.25\n")


def test_default_filename_decimals_and_no_timestamp(tmp_path):
    run(tmp_path, 'decimals="1" timestamp="no"', ticks=2)
    assert (tmp_path / "output.txt").read_text() == (
        "A/1\tB/2\n"
        "1.0\t1.50\t-2.25\n"
        "2.0\t1.50\t-2.25\n")


def test_2d_input_is_written_flattened(tmp_path):
    extra = ('<module class="Constant" name="M" data="1 2; 3 4"/>\n'
             '<connection source="M.OUTPUT" target="O.M" delay="0"/>\n')
    run(tmp_path, 'filename="out.txt" decimals="0"', extra=extra, ticks=1,
        columns=COLUMNS + '<column name="M"/>')
    assert (tmp_path / "out.txt").read_text() == (
        "T/1\tA/1\tB/2\tM/4\n"
        "0\t1\t1.50\t-2.25\t1\t2\t3\t4\n")


# Sweep 0..2 step 1 gives 1, 2, 0, 1, 2, 0 on ticks 0..5.
GATE = ('<module class="Sweep" name="G" min="0" max="2" step="1"/>\n'
        '<connection source="G.OUTPUT" target="O.WRITE" delay="0"/>\n')


def ticks_written(path):
    lines = path.read_text().splitlines()
    assert lines[0] == "T/1\tA/1\tB/2"
    return [int(line.split("\t")[0]) for line in lines[1:]]


def test_write_gates_lines(tmp_path):
    run(tmp_path, 'filename="out.txt"', extra=GATE, ticks=6)
    assert ticks_written(tmp_path / "out.txt") == [0, 1, 3, 4]


def test_single_trig_writes_on_rising_edges_only(tmp_path):
    run(tmp_path, 'filename="out.txt" single_trig="yes"', extra=GATE, ticks=6)
    assert ticks_written(tmp_path / "out.txt") == [0, 3]


def test_write_zero_gives_only_the_header(tmp_path):
    extra = ('<module class="Constant" name="Z" data="0"/>\n'
             '<connection source="Z.OUTPUT" target="O.WRITE" delay="0"/>\n')
    run(tmp_path, 'filename="out.txt"', extra=extra, ticks=3)
    assert (tmp_path / "out.txt").read_text() == "T/1\tA/1\tB/2\n"


def test_newfile_starts_numbered_files(tmp_path):
    # Sweep -1..1 step 1 gives 0, 1, -1, 0, 1, -1 on ticks 0..5: rises on ticks 1 and 4.
    extra = ('<module class="Sweep" name="N" min="-1" max="1" step="1"/>\n'
             '<connection source="N.OUTPUT" target="O.NEWFILE" delay="0"/>\n')
    run(tmp_path, 'filename="out_%02d.txt"', extra=extra, ticks=6)
    assert ticks_written(tmp_path / "out_00.txt") == [0]
    assert ticks_written(tmp_path / "out_01.txt") == [1, 2, 3]
    assert ticks_written(tmp_path / "out_02.txt") == [4, 5]
    assert not (tmp_path / "out_03.txt").exists()


def test_directory_gets_a_new_number_each_run(tmp_path):
    run(tmp_path, 'filename="out.txt" directory="runs"', ticks=1)
    run(tmp_path, 'filename="out.txt" directory="runs"', ticks=2)
    assert ticks_written(tmp_path / "runs_0" / "out.txt") == [0]
    assert ticks_written(tmp_path / "runs_1" / "out.txt") == [0, 1]


def test_inputfile_reads_what_outputfile_wrote(tmp_path):
    run(tmp_path, 'filename="out.txt"', ticks=3)
    path = tmp_path / "reader.ikg"
    path.write_text('<group name="Reader">\n'
                    '<module class="InputFile" name="F" filename="out.txt"/>\n</group>\n')
    net = ikaros.load(str(path))
    try:
        got = []
        for _ in range(3):
            net.step()
            got.append((net.output("F.T").tolist(), net.output("F.A").tolist(),
                        net.output("F.B").tolist()))
        assert got == [([t], [t + 1], [1.5, -2.25]) for t in range(3)]
    finally:
        net.close()


def test_example_runs(tmp_path):
    shutil.copy(EXAMPLE, tmp_path / "example.ikg")
    net = ikaros.load(str(tmp_path / "example.ikg"))
    try:
        net.run(ticks=5)
        assert net.tick == 5
    finally:
        net.close()
    lines = (tmp_path / "output" / "outputfile_example.txt").read_text().splitlines()
    assert len(lines) == 6
    assert np.array(lines[1].split("\t"), float)[0] == 0


# --- the Ikaros 3 interface: INPUT, formats, timestamp modes -------------------------------------
# W is 1, 2, 3 ... on ticks 0, 1, 2 ...; C is [1.5, -2.25].
V3 = ('<module class="Sweep" name="W" min="0" max="100" step="1"/>\n'
      '<module class="Constant" name="C" data="1.5 -2.25"/>\n'
      '<module class="Constant" name="M" data="1 2; 3 4"/>\n')


def run_v3(tmp_path, attributes, connections, ticks=2, **overrides):
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">\n{V3}'
                    f'<module class="OutputFile" name="O" {attributes}/>\n'
                    + "".join(_connection(c) for c in connections) + '</group>\n')
    net = ikaros.load(str(path), **overrides)
    try:
        net.run(ticks=ticks)
    finally:
        net.close()


def _connection(source):
    """A connection into O.INPUT from ``source``, or from ``(source, label)``."""
    source, label = source if isinstance(source, tuple) else (source, None)
    label = f" label={quoteattr(label)}" if label is not None else ""
    return f'<connection source="{source}" target="O.INPUT" delay="0"{label}/>\n'


def test_v3_csv_with_tick_stamps(tmp_path):
    run_v3(tmp_path, 'filename="out.csv" decimals="2"', ["W.OUTPUT", "C.OUTPUT"])
    # an Ikaros 2 file (its Sweep): the connection declared last comes first
    assert (tmp_path / "out.csv").read_text() == (
        "tick,INPUT[0],INPUT[1],INPUT[2]\n"
        "0,1.50,-2.25,1.00\n"
        "1,1.50,-2.25,2.00\n")


def test_v3_csv_is_read_back_by_inputfile(tmp_path):
    run_v3(tmp_path, 'filename="out.csv" timestamp="none"', ["C.OUTPUT"])
    (tmp_path / "back").mkdir()
    model = tmp_path / "back" / "model.ikg"
    model.write_text('<group name="Back"><module class="InputFile" name="F" '
                     'filename="../out.csv"/></group>')
    net = ikaros.load(str(model))
    try:
        net.step()
        assert net.output("F.INPUT").tolist() == [1.5, -2.25]
    finally:
        net.close()


@pytest.mark.parametrize("stamp, first, second", [
    ("line", "0", "1"), ("tick", "0", "1"), ("time", "0", "0.25"),
])
def test_v3_timestamp_modes(tmp_path, stamp, first, second):
    run_v3(tmp_path, f'filename="out.tsv" timestamp="{stamp}" decimals="0"', ["W.OUTPUT"],
           tick_duration="0.25")
    assert (tmp_path / "out.tsv").read_text() == (
        f"{stamp}\tINPUT\n{first}\t1\n{second}\t2\n")


def test_v3_timestamp_none_and_headerless_custom_delimiter(tmp_path):
    run_v3(tmp_path, 'filename="out.csv" timestamp="none" header="no" delimiter=";" '
                     'decimals="1"', ["C.OUTPUT"])
    assert (tmp_path / "out.csv").read_text() == "1.5;-2.2\n1.5;-2.2\n"


def test_v3_full_precision(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test"><module class="Constant" name="K" '
                    'data="1.23456 1e-20 1e20"/>'
                    '<module class="OutputFile" name="O" filename="out.csv" '
                    'number_format="full" timestamp="none"/>'
                    '<connection source="K.OUTPUT" target="O.INPUT" delay="0"/></group>')
    net = ikaros.load(str(path))
    net.run(ticks=1)
    net.close()
    assert (tmp_path / "out.csv").read_text().splitlines()[1] == "1.23456,1e-20,1e+20"


def test_v3_jsonl_keeps_shapes_and_writes_null(tmp_path):
    run_v3(tmp_path, 'filename="out.jsonl"', [("M.OUTPUT", "m")])
    lines = (tmp_path / "out.jsonl").read_text().splitlines()
    assert lines == ['{"tick":0,"m":[[1,2],[3,4]]}', '{"tick":1,"m":[[1,2],[3,4]]}']
    path = tmp_path / "nan.ikg"
    path.write_text('<group name="Test"><module class="Constant" name="K" '
                    'data="nan inf -inf"/>'
                    '<module class="OutputFile" name="O" filename="nan.jsonl" format="jsonl" '
                    'timestamp="tick"/>'
                    '<connection source="K.OUTPUT" target="O.INPUT" delay="0" label="k"/>'
                    '</group>')
    net = ikaros.load(str(path))
    net.run(ticks=1)
    net.close()
    # an Ikaros 3 file by its signs (INPUT and a label): the first tick is 1
    assert (tmp_path / "nan.jsonl").read_text() == '{"tick":1,"k":[null,null,null]}\n'


def test_v3_json_array_is_valid_while_written_and_after(tmp_path):
    run_v3(tmp_path, 'filename="out.json" timestamp="line"', [("W.OUTPUT", "w")], ticks=3)
    assert json.loads((tmp_path / "out.json").read_text()) == [
        {"line": 0, "w": 1}, {"line": 1, "w": 2}, {"line": 2, "w": 3}]


def test_v3_empty_json_recording_is_an_empty_array(tmp_path):
    (tmp_path / "g.txt").write_text("G/1\n0\n0\n")
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test"><module class="InputFile" name="G" filename="g.txt"/>'
                    '<module class="Constant" name="C" data="1"/>'
                    '<module class="OutputFile" name="O" filename="out.json" format="json"/>'
                    '<connection source="C.OUTPUT" target="O.INPUT" delay="0" label="c"/>'
                    '<connection source="G.G" target="O.WRITE" delay="0"/></group>')
    net = ikaros.load(str(path))
    net.run(ticks=2)
    net.close()
    assert json.loads((tmp_path / "out.json").read_text()) == []


def test_v2_columns_and_v3_input_together_in_csv(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">\n{SOURCES}'
                    '<module class="OutputFile" name="O" filename="out.csv" decimals="1" '
                    f'format="csv">{COLUMNS}</module>\n'
                    '<module class="OutputFile" name="V2" filename="v2.csv" decimals="1">'
                    f'{COLUMNS}</module>\n'
                    '<connection source="W.OUTPUT" target="V2.A" delay="0"/>\n'
                    '<connection source="C.OUTPUT" target="V2.B" delay="0"/>\n'
                    '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/></group>')
    net = ikaros.load(str(path))
    net.run(ticks=1)
    net.close()
    assert (tmp_path / "out.csv").read_text() == (
        "tick,A,B[0],B[1],INPUT[0],INPUT[1]\n0,1.0,1.50,-2.25,1.5,-2.2\n")
    # with <column> elements and no format, the Ikaros 2 text table, whatever the name
    assert (tmp_path / "v2.csv").read_text() == "T/1\tA/1\tB/2\n0\t1.0\t1.50\t-2.25\n"


@pytest.mark.parametrize("attributes, message", [
    ('timestamp="sometimes"', 'timestamp "sometimes" must be tick'),
    ('filename="o.csv" delimiter=";;"', 'delimiter ";;" must be one character'),
    ('filename="o.csv" delimiter="&quot;"', "not a quote"),
    ('format="xml"', '"xml" is not one of'),
])
def test_v3_bad_settings_are_build_errors(tmp_path, attributes, message):
    with pytest.raises(ModelError, match=message):
        run_v3(tmp_path, attributes, ["C.OUTPUT"])


def test_v3_hash_numbering_and_single_trigger(tmp_path):
    # G: 0, 1, 1, 0, 1 -> single_trigger writes on ticks 1 and 4; NEWFILE rises on tick 3
    (tmp_path / "g.txt").write_text("G/1 N/1\n0 0\n1 0\n1 0\n0 1\n1 1\n")
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test" dialect="2">'
                    '<module class="InputFile" name="F" filename="g.txt"/>'
                    '<module class="Constant" name="C" data="7"/>'
                    '<module class="OutputFile" name="O" filename="out_##.csv" '
                    'single_trigger="yes" decimals="0"/>'
                    '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/>'
                    '<connection source="F.G" target="O.WRITE" delay="0"/>'
                    '<connection source="F.N" target="O.NEWFILE" delay="0"/></group>')
    net = ikaros.load(str(path))
    net.run(ticks=5)
    net.close()
    assert (tmp_path / "out_00.csv").read_text() == "tick,INPUT\n1,7\n"
    assert (tmp_path / "out_01.csv").read_text() == "tick,INPUT\n4,7\n"


# --- the Ikaros 3 interface: connections named by their labels -----------------------------------
def test_v3_csv_columns_are_named_by_the_labels_and_quoted_when_needed(tmp_path):
    run_v3(tmp_path, 'filename="out.csv" decimals="1"',
           [("C.OUTPUT", 'a,b'), ("W.OUTPUT", 'say "w"'), "M.OUTPUT"], ticks=1)
    assert (tmp_path / "out.csv").read_text() == (
        'tick,"a,b[0]","a,b[1]","say ""w""",M.OUTPUT[0][0],M.OUTPUT[0][1],M.OUTPUT[1][0],'
        'M.OUTPUT[1][1]\n'
        '0,1.5,-2.2,1.0,1.0,2.0,3.0,4.0\n')


def test_v3_jsonl_keeps_each_connection_with_its_shape_and_escapes_labels(tmp_path):
    run_v3(tmp_path, 'filename="out.jsonl" decimals="2"',
           [("M.OUTPUT", "weights"), ("C.OUTPUT", 'b"1'), ("W.OUTPUT", "w")], ticks=1)
    text = (tmp_path / "out.jsonl").read_text()
    assert text == '{"tick":0,"weights":[[1,2],[3,4]],"b\\"1":[1.5,-2.25],"w":1}\n'
    assert json.loads(text) == {"tick": 0, "weights": [[1, 2], [3, 4]], 'b"1': [1.5, -2.25],
                                "w": 1}


def test_v3_jsonl_writes_a_delay_window_as_an_outer_array(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test">' + V3 +
                    '<module class="OutputFile" name="O" filename="out.jsonl" '
                    'timestamp="none"/>'
                    '<connection source="W.OUTPUT" target="O.INPUT" delay="0:2" '
                    'label="history"/></group>')
    net = ikaros.load(str(path))
    net.run(ticks=3)
    net.close()
    # an Ikaros 2 file (its Sweep): the window's longest delay first
    assert (tmp_path / "out.jsonl").read_text().splitlines() == [
        '{"history":[[0],[0],[1]]}', '{"history":[[0],[1],[2]]}',
        '{"history":[[1],[2],[3]]}']


@pytest.mark.parametrize("fmt, connections, message", [
    ("jsonl", ["C.OUTPUT"], "JSONL needs a label on every connection into INPUT; the one "
                            "from C.OUTPUT has none"),
    ("json", [("C.OUTPUT", "x"), "W.OUTPUT"], "JSON needs a label on every connection into "
                                              "INPUT; the one from W.OUTPUT has none"),
    ("jsonl", [("C.OUTPUT", "x"), ("W.OUTPUT", "x")], 'the label "x" is used twice'),
    ("json", [("C.OUTPUT", "tick")], 'the label "tick" is reserved for the time stamp'),
])
def test_v3_json_labels_must_be_there_differ_and_not_be_the_stamp(tmp_path, fmt, connections,
                                                                   message):
    with pytest.raises(ModelError, match=f"While initializing module O: .*{message}"):
        run_v3(tmp_path, f'filename="out.{fmt}"', connections)


def test_v3_timestamp_none_frees_nothing_but_tick(tmp_path):
    run_v3(tmp_path, 'filename="out.jsonl" timestamp="line"', [("C.OUTPUT", "time")], ticks=1)
    assert (tmp_path / "out.jsonl").read_text() == '{"line":0,"time":[1.5,-2.25]}\n'
    with pytest.raises(ModelError, match='the label "line" is reserved'):
        run_v3(tmp_path, 'filename="out.jsonl" timestamp="line"', [("C.OUTPUT", "line")])


# --- append, rollover --------------------------------------------------------------------------
def test_v3_append_keeps_the_records_and_does_not_repeat_the_header(tmp_path):
    (tmp_path / "out.csv").write_text("tick,c\n7,1\n")
    run_v3(tmp_path, 'filename="out.csv" append="yes" decimals="0"', [("W.OUTPUT", "c")])
    assert (tmp_path / "out.csv").read_text() == "tick,c\n7,1\n0,1\n1,2\n"


def test_v3_append_to_a_file_with_another_header_is_an_error(tmp_path):
    (tmp_path / "out.csv").write_text("tick,other\n7,1\n")
    with pytest.raises(ModelError, match="cannot append: its header 'tick,other' differs "
                                         "from this one, 'tick,c'"):
        run_v3(tmp_path, 'filename="out.csv" append="yes"', [("W.OUTPUT", "c")])
    assert (tmp_path / "out.csv").read_text() == "tick,other\n7,1\n"


def test_v3_append_to_a_json_array_keeps_it_one_valid_array(tmp_path):
    (tmp_path / "out.json").write_text('[\n{"tick":7,"c":9}\n]\n')
    run_v3(tmp_path, 'filename="out.json" append="yes"', [("W.OUTPUT", "c")], ticks=1)
    assert (tmp_path / "out.json").read_text() == '[\n{"tick":7,"c":9},\n{"tick":0,"c":1}\n]\n'
    (tmp_path / "empty.json").write_text('[]')
    run_v3(tmp_path, 'filename="empty.json" append="yes"', [("W.OUTPUT", "c")], ticks=1)
    assert json.loads((tmp_path / "empty.json").read_text()) == [{"tick": 0, "c": 1}]
    (tmp_path / "bad.json").write_text('{"tick": 1}')
    with pytest.raises(ModelError, match="cannot append: it is not a JSON array"):
        run_v3(tmp_path, 'filename="bad.json" append="yes"', [("W.OUTPUT", "c")])


def _rollover(tmp_path, filename, attributes="", ticks=3):
    # N: 0, 1, 0, 1 ... rises on ticks 1 and 3
    (tmp_path / "n.txt").write_text("N/1\n0\n1\n0\n1\n0\n")
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test"><module class="InputFile" name="F" filename="n.txt"/>'
                    '<module class="Sweep" name="W" min="0" max="100" step="1"/>'
                    f'<module class="OutputFile" name="O" filename="{filename}" {attributes}/>'
                    '<connection source="W.OUTPUT" target="O.INPUT" delay="0" label="w"/>'
                    '<connection source="F.N" target="O.NEWFILE" delay="0"/></group>')
    net = ikaros.load(str(path))
    try:
        net.run(ticks=ticks)
        return [e[3] for e in net.log if e[1] == WARNING]
    finally:
        net.close()


def test_v3_newfile_closes_each_json_array(tmp_path):
    assert _rollover(tmp_path, "r_#.json", 'start_index="3"') == []
    assert (tmp_path / "r_3.json").read_text() == '[\n{"tick":0,"w":1}\n]\n'
    assert (tmp_path / "r_4.json").read_text() == '[\n{"tick":1,"w":2},\n{"tick":2,"w":3}\n]\n'


def test_v3_a_failed_rollover_keeps_the_current_file(tmp_path):
    warnings = _rollover(tmp_path, "r_#.csv", 'start_index="8" decimals="0"', ticks=5)
    assert (tmp_path / "r_8.csv").read_text() == "tick,w\n0,1\n"
    assert (tmp_path / "r_9.csv").read_text() == "tick,w\n1,2\n2,3\n3,4\n4,5\n"
    assert warnings == [f'cannot start a new file: file number 10 does not fit in "r_#.csv"; '
                        f'continuing with "{tmp_path}/r_9.csv"']


def test_v3_start_index_must_fit_the_counter(tmp_path):
    with pytest.raises(ModelError, match='start_index 100 does not fit in "r_##.csv"'):
        _rollover(tmp_path, "r_##.csv", 'start_index="100"')


def test_v3_jsonl_with_labels_is_read_back_by_inputfile(tmp_path):
    run_v3(tmp_path, 'filename="out.jsonl"', [("M.OUTPUT", "weights"), ("W.OUTPUT", "w")])
    (tmp_path / "back").mkdir()
    model = tmp_path / "back" / "model.ikg"
    model.write_text('<group name="Back"><module class="InputFile" name="F" '
                     'filename="../out.jsonl"/></group>')
    net = ikaros.load(str(model))
    try:
        net.step()
        assert net.output("F.weights").tolist() == [[1, 2], [3, 4]]
        assert net.output("F.w").tolist() == [1]
        assert net.output("F.tick").tolist() == [0]     # held in F's attribute tick_
        net.step()
        assert net.output("F.w").tolist() == [2]
    finally:
        net.close()


def test_existing_file_error_refuses_and_leaves_the_file(tmp_path):
    (tmp_path / "out.csv").write_text("keep\n")
    with pytest.raises(ModelError, match='OutputFile ".*out.csv" already exists '
                                         r'\(existing_file="error"'):
        run_v3(tmp_path, 'filename="out.csv" existing_file="error"', ["C.OUTPUT"])
    assert (tmp_path / "out.csv").read_text() == "keep\n"


def test_existing_file_append_and_overwrite(tmp_path):
    run_v3(tmp_path, 'filename="out.csv" existing_file="error" decimals="1"', ["C.OUTPUT"])
    run_v3(tmp_path, 'filename="out.csv" existing_file="append" decimals="1"', ["C.OUTPUT"],
           ticks=1)
    assert (tmp_path / "out.csv").read_text() == (
        "tick,INPUT[0],INPUT[1]\n0,1.5,-2.2\n1,1.5,-2.2\n0,1.5,-2.2\n")
    run_v3(tmp_path, 'filename="out.csv" existing_file="overwrite" decimals="1"',
           ["C.OUTPUT"], ticks=1)
    assert (tmp_path / "out.csv").read_text() == "tick,INPUT[0],INPUT[1]\n0,1.5,-2.2\n"


def test_a_new_file_that_exists_is_not_begun_with_existing_file_error(tmp_path):
    (tmp_path / "r_1.csv").write_text("keep\n")
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test">\n<module class="Constant" name="C" data="5"/>'
                    '<module class="Sweep" name="N" min="0" max="1" step="1"/>'
                    '<module class="OutputFile" name="O" filename="r_#.csv" decimals="0" '
                    'existing_file="error"/>'
                    '<connection source="C.OUTPUT" target="O.INPUT" delay="0" label="v"/>'
                    '<connection source="N.OUTPUT" target="O.NEWFILE" delay="0"/></group>')
    with ikaros.load(str(path)) as net:
        net.run(ticks=2)
        assert any("cannot start a new file" in e[3] and "already exists" in e[3]
                   for e in net.log)
    assert (tmp_path / "r_1.csv").read_text() == "keep\n"
    assert (tmp_path / "r_0.csv").read_text() == "tick,v\n0,5\n1,5\n"


def test_flush_interval_writes_to_the_disk_every_n_records(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test"><module class="Constant" name="C" data="5"/>'
                    '<module class="OutputFile" name="O" filename="out.csv" decimals="0" '
                    'flush_interval="3"/>'
                    '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/></group>')
    with ikaros.load(str(path)) as net:
        on_disk = []
        for _ in range(4):
            net.step()
            on_disk.append((tmp_path / "out.csv").read_text().count("\n"))
    assert on_disk == [1, 1, 4, 4]                  # the header, then three records at once
    assert (tmp_path / "out.csv").read_text().count("\n") == 5      # all of them when closed


def test_ikaros_3_defaults_csv_output_time_stamps_and_no_overwriting(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test" tick_duration="0.5"><module class="Constant" name="C" '
                    'data="5"/><module class="OutputFile" name="O"/>'
                    '<connection source="C.OUTPUT" target="O.INPUT" delay="0"/></group>')
    with ikaros.load(str(path), dialect="3") as net:
        net.run(ticks=2)
    assert (tmp_path / "output.csv").read_text() == "time,INPUT\n0.5,5.0000\n1,5.0000\n"
    with pytest.raises(ModelError, match="already exists"):
        ikaros.load(str(path), dialect="3")
