"""`ikaros-sim ssc32|epuck|opc` print the address to use, answer there, and stop on SIGTERM."""
from __future__ import annotations

import os
import signal
import subprocess
import sys

import numpy as np
import pytest

from ikaros.hardware.epuck import Epuck
from ikaros.hardware.opc import OPCClient
from ikaros.hardware.ssc32 import SSC32

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(
    __file__)))))


def use_ssc32(path):
    board = SSC32(path)
    try:
        board.move({3: 1700})
        return board.pulse_widths([3]) == [1700]
    finally:
        board.close()


def use_epuck(path):
    robot = Epuck(path)
    try:
        robot.set_speed(100, 100)
        robot.set_speed(0, 0)                      # --step 0.5: 50 steps each
        return robot.encoders() == [50, 50]
    finally:
        robot.close()


def use_opc(path):
    client = OPCClient(path)
    try:
        client.set_pixels(1, np.ones((3, 3)))
        return path.startswith("127.0.0.1:")
    finally:
        client.close()


@pytest.mark.parametrize("argv, use", [(["ssc32"], use_ssc32),
                                       (["epuck", "--step", "0.5", "--obstacles", "none"],
                                        use_epuck),
                                       (["opc"], use_opc)], ids=["ssc32", "epuck", "opc"])
def test_simulator_command(argv, use):
    env = dict(os.environ, PYTHONPATH=ROOT)
    process = subprocess.Popen([sys.executable, "-m", "ikaros.hardware.sim_cli", *argv],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=env)
    try:
        path = process.stdout.readline().strip()
        assert path, process.stderr.read()
        assert use(path)
        assert "Ctrl-C stops it" in process.stderr.readline()
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=10) == 0
    finally:
        if process.poll() is None:
            process.kill()
            process.wait(timeout=10)


def test_a_sigterm_while_the_simulator_starts_ends_it_cleanly():
    starting = ("import os, signal, sys\n"
                "from ikaros.hardware import sim_cli, ssc32_sim\n"
                "start = ssc32_sim.start\n"
                "def start_and_get_terminated(options):\n"
                "    os.kill(os.getpid(), signal.SIGTERM)\n"
                "    return start(options)\n"
                "ssc32_sim.start = start_and_get_terminated\n"
                "sys.exit(sim_cli.main(['ssc32']))\n")
    result = subprocess.run([sys.executable, "-c", starting], capture_output=True, text=True,
                            env=dict(os.environ, PYTHONPATH=ROOT), timeout=30)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("/dev/pts/")


def test_bad_simulator_options_are_reported():
    env = dict(os.environ, PYTHONPATH=ROOT)
    result = subprocess.run([sys.executable, "-m", "ikaros.hardware.sim_cli", "epuck",
                             "--x", "-1"], capture_output=True, text=True, env=env, timeout=30)
    assert result.returncode == 1
    assert "e-puck simulator: the start position (-1.0, 0.2) is inside a wall" in result.stderr


def test_a_device_string_opens_a_simulator_or_names_a_real_device():
    from ikaros.hardware.simulators import open_device_string
    assert open_device_string("/dev/ttyUSB0") == ("/dev/ttyUSB0", None)
    path, simulator = open_device_string("sim:ssc32")
    try:
        assert path == simulator.path and path.startswith("/dev/pts/")
        assert use_ssc32(path)
    finally:
        simulator.stop()
