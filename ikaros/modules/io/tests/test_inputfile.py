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
