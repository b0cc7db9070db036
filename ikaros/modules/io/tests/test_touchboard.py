"""Tests of TouchBoard against a simulated board on a pseudo-terminal, and of
TouchBoardGraph."""
import threading

import pytest
import serial

from ikaros.errors import ModelError
from ikaros.hardware.pty_device import PtyDevice
from ikaros.hardware.touchboard import DataStreamReader, parse_line
from ikaros.hardware.touchboard_sim import SimulatedTouchBoard
from ikaros.testing import load_body as load, step_until


@pytest.fixture
def board():
    with SimulatedTouchBoard() as sim:
        yield sim


def test_values_and_touches_come_from_the_board(tmp_path, board):
    fdat = list(range(600, 613))
    board.set("FDAT", fdat)
    board.set("DIFF", [5] * 13)
    board.set("TOUCH", [0, 1] + [0] * 10 + [1])
    net = load(tmp_path, f'<module class="TouchBoard" name="T" port="{board.path}"/>'
                         f'<module class="TouchBoard" name="D" port="{board.path}" '
                         f'data="DIFF" electrodes="13"/>')
    try:
        assert net.output("T.OUTPUT").shape == (11,)
        # the board may send a batch made between two of the set() calls above first
        step_until(net, lambda: net.output("T.OUTPUT")[0] == 600
                   and net.output("T.TOUCHED")[1] == 1)
        assert net.output("T.OUTPUT").tolist() == fdat[:11]
        assert net.output("T.TOUCHED").tolist() == [0, 1] + [0] * 9
        board.set("FDAT", [700] * 13)
        step_until(net, lambda: net.output("T.OUTPUT")[0] == 700)
        assert net.output("T.OUTPUT").tolist() == [700] * 11
    finally:
        net.close()


def test_a_port_that_cannot_be_opened_is_a_load_error(tmp_path):
    with pytest.raises(ModelError, match='cannot open the Touch Board\'s port "/no/such"'):
        load(tmp_path, '<module class="TouchBoard" name="T" port="/no/such"/>')


def test_the_simulated_board_streams_on_its_pseudo_terminal_until_stopped():
    board = SimulatedTouchBoard(interval=0.005)
    assert isinstance(board, PtyDevice)
    with board:
        board.set("TOUCH", [1] * 13)
        port = serial.Serial(board.path, 115200, timeout=1.0)
        try:
            reader, lines = DataStreamReader(), []
            while ("TOUCH", [1] * 13) not in lines:
                chunk = port.read(256)
                assert chunk, "the board sent nothing"
                lines += reader.feed(chunk)
        finally:
            port.close()
    assert "touchboard-sim-stream" not in [t.name for t in threading.enumerate()]


def test_the_datastream_lines_are_parsed_across_reads():
    reader = DataStreamReader()
    assert reader.feed(b"FDAT: 1 2 3\r\nTOU") == [("FDAT", [1, 2, 3])]
    assert reader.feed(b"CH: 0 1\r\nnoise\r\nDIFF: x\r\n") == [("TOUCH", [0, 1])]
    assert parse_line("BVAL: 4 5") == ("BVAL", [4, 5])
    assert parse_line("OTHER: 4") is None


def test_the_graph_draws_one_bar_per_value(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 512 1024 2000 -5"/>'
                         '<module class="TouchBoardGraph" name="G" height="4" '
                         'bar_width="2"/>'
                         '<connection source="C.OUTPUT" target="G.INPUT"/>')
    try:
        net.step()
        graph = net.output("G.GRAPH")
        assert graph.shape == (4, 14)
        bars = graph[:, ::3]                       # the first column of each bar
        assert bars.sum(axis=0).tolist() == [0, 2, 4, 4, 0]
        assert graph[:, 2].tolist() == [0, 0, 0, 0]          # the gap between bars
        assert graph[:, 4].tolist() == [0, 0, 1, 1]          # bars grow from the bottom
    finally:
        net.close()
