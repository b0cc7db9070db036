"""Tests of the InputFile module."""
import shutil
from pathlib import Path

import numpy as np
import pytest

import ikaros
from ikaros.errors import ModelError

EXAMPLES = Path(__file__).resolve().parents[4] / "examples" / "modules"

DATA = """# a comment before the header
X/2 Y/1

1 2 3   # a comment after values
4 5 6
# a comment between lines

7 8 9
"""
ROWS = [([1, 2], [3]), ([4, 5], [6]), ([7, 8], [9])]


def load(tmp_path, attributes, data=DATA, extra="", **overrides):
    (tmp_path / "data.txt").write_text(data)
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">\n<module class="InputFile" name="F" '
                    f'filename="data.txt" {attributes}/>\n{extra}</group>\n')
    return ikaros.load(str(path), **overrides)


def values(net):
    return (net.output("F.X").tolist(), net.output("F.Y").tolist())


def test_one_line_per_tick_then_end_of_file(tmp_path):
    net = load(tmp_path, "")
    try:
        assert net.output("F.X").shape == (2,) and net.output("F.Y").shape == (1,)
        assert values(net) == ([0, 0], [0])                 # init
        net.step()
        assert values(net) == ROWS[0]
        net.step()
        assert values(net) == ROWS[1]
        net.run(ticks=10)               # the last line, then end of file stops the run
        assert net.tick == 3
        assert values(net) == ROWS[2]
    finally:
        net.close()


def test_no_end_of_file_gives_zeros_forever(tmp_path):
    net = load(tmp_path, 'send_end_of_file="no"')
    try:
        got = []
        for _ in range(6):
            net.step()
            got.append(values(net))
        assert got == ROWS + [([0, 0], [0])] * 3
        assert net.tick == 6
    finally:
        net.close()


def test_extend_runs_longer_before_end_of_file(tmp_path):
    net = load(tmp_path, 'extend="2"')
    try:
        net.run(ticks=20)
        assert net.tick == 5            # 3 lines + 2 extra ticks
        assert values(net) == ([0, 0], [0])
    finally:
        net.close()


def test_iterations_and_repetitions(tmp_path):
    net = load(tmp_path, 'iterations="2" repetitions="2" send_end_of_file="no"')
    try:
        got = []
        for _ in range(14):
            net.step()
            got.append(values(net))
        expected = [r for r in ROWS for _ in range(2)] * 2 + [([0, 0], [0])] * 2
        assert got == expected
    finally:
        net.close()
    net = load(tmp_path, 'iterations="2" repetitions="2"')
    try:
        net.run(ticks=100)
        assert net.tick == 12
    finally:
        net.close()


def test_iterations_zero_repeats_forever(tmp_path):
    net = load(tmp_path, 'iterations="0"')
    try:
        for tick in range(10):
            net.step()
            assert values(net) == ROWS[tick % 3]
        net.run(ticks=20)
        assert net.tick == 30
    finally:
        net.close()


def test_static_outputs_the_whole_file(tmp_path):
    net = load(tmp_path, 'type="static"')
    try:
        assert np.array_equal(net.output("F.X"), [[1, 2], [4, 5], [7, 8]])
        net.run(ticks=5)
        assert net.tick == 5
        assert np.array_equal(net.output("F.X"), [[1, 2], [4, 5], [7, 8]])
        assert np.array_equal(net.output("F.Y"), [[3], [6], [9]])
    finally:
        net.close()


def test_outputs_feed_other_modules(tmp_path):
    extra = ('<module class="Sum" name="S"/>\n'
             '<connection source="F.X" target="S.INPUT" delay="0"/>\n')
    net = load(tmp_path, "", data="X/3\n1 2 3\n0.5 0.25 -1\n", extra=extra)
    try:
        net.step()
        assert net.output("S.OUTPUT")[0] == 6
        net.step()
        assert net.output("S.OUTPUT")[0] == -0.25
    finally:
        net.close()


def test_header_name_without_width_is_one_element(tmp_path):
    net = load(tmp_path, "", data="A B/2\n1 2 3\n")
    try:
        net.step()
        assert net.output("F.A").tolist() == [1]
        assert net.output("F.B").tolist() == [2, 3]
    finally:
        net.close()


def test_missing_file_is_a_build_error(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text('<group name="Test">\n<module class="InputFile" name="F" '
                    'filename="nothere.txt"/>\n</group>\n')
    with pytest.raises(ModelError, match="nothere.txt"):
        ikaros.load(str(path))


def test_bad_header_is_a_build_error(tmp_path):
    with pytest.raises(ModelError, match="X/0"):
        load(tmp_path, "", data="X/0\n1\n")


def test_print_iteration(tmp_path):
    net = load(tmp_path, 'iterations="2" print_iteration="yes"')
    try:
        net.run(ticks=10)
        assert net.tick == 6
        printed = [(tick, message) for tick, _level, where, message in net.log
                   if where.split(".")[-1] == "F"]
        assert printed[:2] == [(0, "iteration 1"), (3, "iteration 2")]
    finally:
        net.close()


def test_bad_data_line_is_a_fatal_error_when_it_is_due(tmp_path):
    net = load(tmp_path, "", data="X/2\n1 2\n3\n5 6\n")
    try:
        net.step()
        assert net.output("F.X").tolist() == [1, 2]
        with pytest.raises(ikaros.RunError, match=r"data.txt:3: expected 2 values, found 1"):
            net.run(ticks=5)
        assert net.tick == 2
    finally:
        net.close()


def test_value_that_is_not_a_number_is_a_fatal_error(tmp_path):
    net = load(tmp_path, "", data="X/1\nabc\n")
    try:
        with pytest.raises(ikaros.RunError, match="not a number"):
            net.run(ticks=3)
        assert net.tick == 1
    finally:
        net.close()


def test_empty_data_ends_at_once(tmp_path):
    net = load(tmp_path, "", data="# nothing but a header\nX/2\n")
    try:
        net.run(ticks=5)
        assert net.tick == 1
        assert net.output("F.X").tolist() == [0, 0]
    finally:
        net.close()


def test_example_runs(tmp_path):
    shutil.copy(EXAMPLES / "InputFile_example.ikg", tmp_path / "example.ikg")
    shutil.copy(EXAMPLES / "inputfile_example.txt", tmp_path / "inputfile_example.txt")
    net = ikaros.load(str(tmp_path / "example.ikg"))
    try:
        net.run(ticks=5)
        assert net.tick == 5
    finally:
        net.close()


# --- the Ikaros 3 formats: CSV, TSV, JSON, JSON Lines -------------------------------------------

def load_file(tmp_path, filename, text, attributes=""):
    (tmp_path / filename).write_text(text)
    path = tmp_path / "model.ikg"
    path.write_text(f'<group name="Test">\n<module class="InputFile" name="F" '
                    f'filename="{filename}" {attributes}/>\n</group>\n')
    return ikaros.load(str(path))


def ticks(net, names, n):
    out = []
    try:
        for _ in range(n):
            net.step()
            out.append(tuple(net.output(f"F.{name}").tolist() for name in names))
    finally:
        net.close()
    return out


def test_v3_csv_by_extension_with_grouped_columns(tmp_path):
    net = load_file(tmp_path, "d.csv", "time,pos[0],pos[1]\n0.5,1,2\n1.5,3,4\n")
    assert net.output("F.time").shape == (1,) and net.output("F.pos").shape == (2,)
    assert ticks(net, ["time", "pos"], 2) == [([0.5], [1, 2]), ([1.5], [3, 4])]


def test_v3_csv_cells_of_several_values_and_legal_names(tmp_path):
    net = load_file(tmp_path, "d.csv", "joint angles,speed (m/s)\n1 2,3\n4 5,6\n")
    assert ticks(net, ["joint_angles", "speed__m_s_"], 2) == [([1, 2], [3]), ([4, 5], [6])]


def test_v3_tsv_custom_space_and_headerless(tmp_path):
    assert ticks(load_file(tmp_path, "d.tsv", "a\tb\n1\t2\n"), ["a", "b"], 1) == [([1], [2])]
    net = load_file(tmp_path, "d.txt", "a;b\n7;8\n", 'format="csv" delimiter=";"')
    assert ticks(net, ["a", "b"], 1) == [([7], [8])]
    net = load_file(tmp_path, "s.txt", "a  b\n1   2\n", 'format="csv" delimiter=" "')
    assert ticks(net, ["a", "b"], 1) == [([1], [2])]
    net = load_file(tmp_path, "h.csv", "1,2,3\n4,5,6\n", 'header="no"')
    assert ticks(net, ["OUTPUT"], 2) == [([1, 2, 3],), ([4, 5, 6],)]


def test_v3_json_array_of_records_with_shapes(tmp_path):
    text = ('[{"x": 1, "weights": [[1, 2], [3, 4]], "on": true},\n'
            ' {"x": 2.5, "weights": [[5, 6], [7, 8]], "on": null}]')
    net = load_file(tmp_path, "d.json", text)
    assert net.output("F.weights").shape == (2, 2)
    got = ticks(net, ["x", "weights", "on"], 2)
    assert got[0] == ([1], [[1, 2], [3, 4]], [1])
    assert got[1][:2] == ([2.5], [[5, 6], [7, 8]]) and np.isnan(got[1][2][0])


def test_v3_jsonl_and_repetitions(tmp_path):
    net = load_file(tmp_path, "d.jsonl", '{"a-b": [1, 2]}\n\n{"a-b": [3, 4]}\n',
                    'repetitions="2"')
    assert ticks(net, ["a-b"], 4) == [([1, 2],), ([1, 2],), ([3, 4],), ([3, 4],)]


def test_v3_static_json_has_a_row_per_record(tmp_path):
    net = load_file(tmp_path, "d.json", '[{"v": [1, 2]}, {"v": [3, 4]}, {"v": [5, 6]}]',
                    'type="static"')
    try:
        net.step()
        assert net.output("F.v").tolist() == [[1, 2], [3, 4], [5, 6]]
    finally:
        net.close()


def test_v3_end_of_file_after_the_last_record(tmp_path):
    net = load_file(tmp_path, "d.jsonl", '{"a": 1}\n{"a": 2}\n')
    try:
        net.run()
        assert net.tick == 2 and net.output("F.a").tolist() == [2]
    finally:
        net.close()


@pytest.mark.parametrize("filename, text, message", [
    ("d.json", '[{"a": [1, 2]}, {"a": [1, 2, 3]}]',
     r'd.json: record 2: "a" has shape \(3,\), but \(2,\) in the first record'),
    ("d.jsonl", '{"a": 1}\n{"b": 1}\n', r"d.jsonl:2: the keys \['b'\] differ"),
    ("d.jsonl", '{"a": 1}\n{"a": \n', r"d.jsonl:2: not valid JSON"),
    ("d.json", '{"a": 1}', "must hold an array of objects"),
    ("d.json", '[{"a": "text"}]', '"a" is not a number'),
    ("d.csv", "a,b\n1,x\n", r'd.csv:2: "x" in column "b" is not a number'),
    ("d.csv", "a,b\n1 2,3\n4,5\n", r'd.csv:3: column "a" holds 1 values, 2 in the first row'),
])
def test_v3_bad_files_are_build_errors(tmp_path, filename, text, message):
    with pytest.raises(ModelError, match=message):
        load_file(tmp_path, filename, text)


def test_v2_text_format_is_still_the_default_for_other_names(tmp_path):
    net = load_file(tmp_path, "d.dat", "X/2\n1 2\n")
    assert ticks(net, ["X"], 1) == [([1, 2],)]


def test_v3_iterations_and_print_iteration(tmp_path):
    net = load_file(tmp_path, "d.csv", "a\n1\n2\n", 'iterations="2" print_iteration="yes"')
    try:
        got = []
        for _ in range(4):
            net.step()
            got.append(net.output("F.a").tolist())
        assert got == [[1], [2], [1], [2]]
        assert [e[3] for e in net.log if e[3].startswith("iteration")] == \
            ["iteration 1", "iteration 2"]
    finally:
        net.close()


def test_v2_table_named_csv_is_still_read_as_ikaros_2(tmp_path):
    net = load_file(tmp_path, "old.csv", "X/2 Y/1\n1 2 3\n")
    assert ticks(net, ["X", "Y"], 1) == [([1, 2], [3])]


def test_ikaros_3_names_the_text_format_text(tmp_path):
    net = load_file(tmp_path, "d.json", "X/2 Y/1\n1 2 3\n4 5 6\n", 'format="text"')
    try:
        net.step()
        assert net.output("F.X").tolist() == [1, 2] and net.output("F.Y").tolist() == [3]
    finally:
        net.close()
