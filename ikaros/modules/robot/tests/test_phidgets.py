"""The Phidgets module: without the library, with the real library and no board, and against
stand-in channels that behave like Phidget22's."""
import sys

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.hardware import phidgets
from ikaros.testing import load_body, wait_for


class FakeError(Exception):
    def __init__(self, details):
        super().__init__(details)
        self.details = details


class FakeBoard:
    serial = 4242
    ratios = [0.1, 0.25, 0.5, 1.0]
    volts = [0.5, 1.0, 2.5, 5.0]
    inputs = [True, False, True]

    def __init__(self):
        self.outputs = {}
        self.triggers = {}
        self.opened = []
        self.closed = 0


def fake_library(board):
    class Channel:
        def __init__(self):
            self.serial, self.index = -1, 0

        def setDeviceSerialNumber(self, serial):
            self.serial = serial

        def setChannel(self, index):
            self.index = index

        def openWaitForAttachment(self, timeout):
            if self.serial not in (-1, board.serial):
                raise FakeError("No Phidgets were detected at all.")
            board.opened.append((type(self).__name__, self.index))

        def getAttached(self):
            return True

        def close(self):
            board.closed += 1

        def getDeviceName(self):
            return "PhidgetInterfaceKit 8/8/8"

        def getDeviceSerialNumber(self):
            return board.serial

        def getDeviceVersion(self):
            return 900

    class VoltageRatioInput(Channel):
        def getVoltageRatio(self):
            return board.ratios[self.index]

        def setVoltageRatioChangeTrigger(self, value):
            board.triggers[self.index] = value

    class VoltageInput(Channel):
        def getVoltage(self):
            return board.volts[self.index]

        def setVoltageChangeTrigger(self, value):
            board.triggers[self.index] = value

    class DigitalInput(Channel):
        def getState(self):
            return board.inputs[self.index]

    class DigitalOutput(Channel):
        def setState(self, state):
            board.outputs[self.index] = state

    return dict(VoltageRatioInput=VoltageRatioInput, VoltageInput=VoltageInput,
                DigitalInput=DigitalInput, DigitalOutput=DigitalOutput,
                PhidgetException=FakeError)


def model(tmp_path, params, outputs="1 0 1 1", delay=0):
    body = (f'<module class="Constant" name="Out" data="{outputs}"/>\n'
            f'<module class="Phidgets" name="P" analog_inputs="4" digital_inputs="3" '
            f'digital_outputs="4" {params}/>\n'
            f'<connection source="Out.OUTPUT" target="P.DIGITAL_INPUTS" delay="{delay}"/>')
    return load_body(tmp_path, body)


@pytest.fixture
def board(monkeypatch):
    board = FakeBoard()
    monkeypatch.setattr(phidgets, "load_library", lambda: fake_library(board))
    return board


def test_inputs_outputs_and_safe_state(tmp_path, board, capsys):
    net = model(tmp_path, 'serial="4242"')
    try:
        assert "PhidgetInterfaceKit 8/8/8, serial number 4242, version 900" in \
            capsys.readouterr().out
        assert board.outputs == {}                            # nothing written at start-up
        assert board.triggers == {i: 0.01 for i in range(4)}  # sensitivity 10 of 1000
        net.step()
        assert board.outputs == {0: True, 1: False, 2: True, 3: True}
        assert net.output("P.ATTACHED").tolist() == [1]
        assert np.allclose(net.output("P.ANALOG_OUTPUTS"), [100, 250, 500, 1000])
        assert net.output("P.DIGITAL_OUTPUTS").tolist() == [1, 0, 1]
    finally:
        net.close()
    assert board.outputs == {0: False, 1: False, 2: False, 3: False}
    assert board.closed == 4 + 3 + 4


def test_outputs_that_have_no_value_from_their_source_yet_are_not_written(tmp_path, board):
    net = model(tmp_path, 'serial="4242" info="no"', delay=2)          # the values arrive on tick 2
    try:
        net.step()
        net.step()
        assert board.outputs == {}
        net.step()
        assert board.outputs == {0: True, 1: False, 2: True, 3: True}
    finally:
        net.close()


def test_the_watchdog_switches_the_outputs_off_when_ticks_stop_and_ticks_resume(tmp_path, board):
    net = model(tmp_path, 'serial="4242" info="no" watchdog="0.2"')
    try:
        net.step()
        assert board.outputs == {0: True, 1: False, 2: True, 3: True}
        assert wait_for(lambda: not any(board.outputs.values()), 3.0)     # no tick for 0.2 s
        net.step()
        assert board.outputs == {0: True, 1: False, 2: True, 3: True}     # written again
        net.command("P", "safe_state")
        assert board.outputs == {0: False, 1: False, 2: False, 3: False}
    finally:
        net.close()


def test_voltages_when_not_ratiometric(tmp_path, board):
    net = model(tmp_path, 'serial="-1" ratiometric="no" sensitivity="20" info="no"')
    try:
        net.step()
        assert np.allclose(net.output("P.ANALOG_OUTPUTS"), [100, 200, 500, 1000])
        assert board.triggers == {i: 0.1 for i in range(4)}   # 20 units of 200 per volt
    finally:
        net.close()


def test_a_board_that_is_not_there_is_named(tmp_path, board):
    with pytest.raises(ModelError, match="no Phidgets InterfaceKit with serial number 176729 "
                       "answered on VoltageRatioInput channel 0"):
        model(tmp_path, 'attach_timeout="100"')
    assert board.opened == []


def test_the_real_library_without_a_board(tmp_path):
    pytest.importorskip("Phidget22", reason="the phidgets extra is not installed")
    with pytest.raises(ModelError, match="no Phidgets InterfaceKit with serial number 176729 "
                       "answered on VoltageRatioInput channel 0 within 100 ms"):
        model(tmp_path, 'attach_timeout="100"')


def test_a_missing_library_names_the_pip_install(tmp_path, monkeypatch):
    for name in [m for m in sys.modules if m.startswith("Phidget22.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "Phidget22", None)        # import Phidget22 fails
    with pytest.raises(ModelError, match=r"pip install 'ikaros\[phidgets\]'"):
        model(tmp_path, "")
