"""The SSC32 module against the virtual SSC-32."""
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.hardware.ssc32_sim import VirtualSSC32
from ikaros.testing import load_body


def model(tmp_path, port, data="0 0.5 1", params='min="1000" max="2000"'):
    body = (f'<module class="Constant" name="In" data="{data}"/>\n'
            f'<module class="SSC32" name="Servos" port="{port}" {params}/>\n'
            '<connection source="In.OUTPUT" target="Servos.INPUT" delay="0"/>')
    return load_body(tmp_path, body)


@pytest.fixture
def board():
    with VirtualSSC32() as device:
        yield device


def moves(device):
    return [c for c in device.commands if c.startswith("#")]


def last_move(device, expected, seconds=1.0):
    """The last move command once ``expected`` has arrived (or after ``seconds``)."""
    deadline = time.monotonic() + seconds
    while moves(device)[-1:] != [expected] and time.monotonic() < deadline:
        time.sleep(0.005)
    return moves(device)[-1]


def test_positions_reach_the_servos_and_come_back(tmp_path, board):
    net = model(tmp_path, board.path)
    try:
        assert board.commands == []                      # nothing moves at start-up
        net.step()
        assert moves(board) == ["#0P1000#1P1500#2P2000"]
        assert np.allclose(net.output("Servos.OUTPUT"), [0, 0.5, 1])
        net.step()
        assert len(moves(board)) == 1                    # unchanged: nothing sent
        net.set_parameter("In.data", "0.25 0.5 1.5")     # 1.5 is clipped to max
        net.step()
        assert moves(board)[-1] == "#0P1250"
        assert np.allclose(net.output("Servos.OUTPUT"), [0.25, 0.5, 1])
    finally:
        net.close()
    assert last_move(board, "#0P0#1P0#2P0") == "#0P0#1P0#2P0"           # safe state: no pulses
    assert [board.pulse(c) for c in range(3)] == [0, 0, 0]


def test_an_input_that_has_no_value_from_its_source_yet_moves_nothing(tmp_path, board):
    """Constant -> Scale -> SSC32 with the default delays (1): the position the model asks for
    reaches the board on tick 2; before it the input holds the zeros of the start, which
    must not be sent as a move to min (#0P500#1P500)."""
    body = (f'<module class="Constant" name="In" data="0.5 0.5"/>\n'
            '<module class="Scale" name="S" factor="1"/>\n'
            f'<module class="SSC32" name="Servos" port="{board.path}"/>\n'
            '<connection source="In.OUTPUT" target="S.INPUT"/>\n'
            '<connection source="S.OUTPUT" target="Servos.INPUT"/>')
    net = load_body(tmp_path, body)
    try:
        net.step()
        net.step()
        assert moves(board) == []
        net.step()
        assert moves(board) == ["#0P1500#1P1500"]
    finally:
        net.close()


def test_channels_per_servo_ranges_move_time_and_speed(tmp_path, board):
    net = model(tmp_path, board.path, "0.5 1", 'channels="4 7" min="1000 600" max="2000 1400" '
                'move_time="20" speed="3000"')
    try:
        net.step()
        assert moves(board) == ["#4P1500S3000#7P1400S3000T20"]
    finally:
        net.close()
    assert last_move(board, "#4P0#7P0") == "#4P0#7P0"


@pytest.mark.parametrize("state, last", [("hold", "#0P1000#1P1500#2P2000"),
                                         ("home", "#0P1200#1P1300#2P1400")])
def test_other_safe_states(tmp_path, board, state, last):
    net = model(tmp_path, board.path, params=f'min="1000" max="2000" home="1200 1300 1400" '
                f'safe_state="{state}"')
    net.step()
    net.close()
    assert last_move(board, last) == last


def test_a_silent_board_stops_the_run_with_its_port_and_reaches_the_safe_state(tmp_path):
    with VirtualSSC32(fault="silent") as device:
        net = model(tmp_path, device.path)
        with pytest.raises(RunError, match=f"SSC-32 at '{device.path}' does not answer"):
            net.step()
        assert last_move(device, "#0P0#1P0#2P0") == "#0P0#1P0#2P0"
        net.close()


def test_bad_parameters_are_named(tmp_path, board):
    with pytest.raises(ModelError, match="min has 2 values"):
        model(tmp_path, board.path, params='min="1000 1100"')
    with pytest.raises(ModelError, match="pulse widths must be in 500..2500"):
        model(tmp_path, board.path, params='max="3000"')
    with pytest.raises(ModelError, match="channels lists 2 channels"):
        model(tmp_path, board.path, params='channels="1 2"')
    with pytest.raises(ModelError, match="cannot open the SSC-32 at '/dev/nothing-here'"):
        model(tmp_path, "/dev/nothing-here")


def test_the_watchdog_makes_idle_servos_safe_and_ticks_resume(tmp_path, board):
    net = model(tmp_path, board.path, params='min="1000" max="2000" watchdog="0.2"')
    try:
        net.step()
        assert last_move(board, "#0P0#1P0#2P0") == "#0P0#1P0#2P0"      # no tick for 0.2 s
        net.step()
        assert moves(board)[-1] == "#0P1000#1P1500#2P2000"              # sent again
        assert np.allclose(net.output("Servos.OUTPUT"), [0, 0.5, 1])
        net.command("Servos", "safe_state")
        assert last_move(board, "#0P0#1P0#2P0") == "#0P0#1P0#2P0"
    finally:
        net.close()


def test_a_script_that_never_closes_leaves_the_servos_off(tmp_path, board):
    script = tmp_path / "script.py"
    script.write_text(
        "import sys, ikaros\n"
        f"net = ikaros.load({str(tmp_path / 'model.ikg')!r})\n"
        "net.step()\n"
        "sys.exit(0)\n")                                   # no close(): the exit hook runs
    model(tmp_path, board.path).close()                    # writes model.ikg
    last_move(board, "#0P0#1P0#2P0")
    board.commands.clear()
    result = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 0, result.stderr
    assert last_move(board, "#0P0#1P0#2P0") == "#0P0#1P0#2P0"
    assert moves(board)[0] == "#0P1000#1P1500#2P2000"


def test_ctrl_c_of_an_ikaros_process_turns_the_servos_off(tmp_path, board):
    path = tmp_path / "servos.ikg"
    path.write_text('<group name="Servos" tick_duration="0.02">\n'
                    '<module class="Constant" name="In" data="0.2 0.8"/>\n'
                    f'<module class="SSC32" name="S" port="{board.path}"/>\n'
                    '<connection source="In.OUTPUT" target="S.INPUT"/>\n</group>\n')
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        p for p in [root, os.environ.get("PYTHONPATH")] if p))
    process = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-r", str(path)],
                               env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        assert last_move(board, "#0P900#1P2100", 20.0) == "#0P900#1P2100"
        process.send_signal(signal.SIGINT)
        process.wait(timeout=10)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait(timeout=10)
    assert last_move(board, "#0P0#1P0") == "#0P0#1P0"
    assert [board.pulse(0), board.pulse(1)] == [0, 0]


def test_an_exception_in_another_module_turns_the_servos_off(tmp_path, board):
    (tmp_path / "Boom.py").write_text(
        "from ikaros import Module\n\n\nclass Boom(Module):\n"
        "    def tick(self):\n"
        "        if self.clock.tick == 2:\n"
        "            raise RuntimeError('boom')\n")
    body = ('<module class="Constant" name="In" data="0 0.5 1"/>\n'
            f'<module class="SSC32" name="Servos" port="{board.path}"/>\n'
            '<module class="Boom" name="B"/>\n'
            '<connection source="In.OUTPUT" target="Servos.INPUT" delay="0"/>')
    net = load_body(tmp_path, body)
    with pytest.raises(RunError, match="RuntimeError: boom"):
        for _ in range(10):
            net.step()
    assert last_move(board, "#0P0#1P0#2P0") == "#0P0#1P0#2P0"
    net.close()
