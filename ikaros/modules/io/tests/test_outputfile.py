"""Tests of the OutputFile module."""
import shutil
from pathlib import Path

import numpy as np

import ikaros

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
