"""Tests of MidiInterface and MidiFilter, through a mido backend that loops messages back in
memory (no MIDI system is needed: ALSA's sequencer is missing on test machines)."""
import sys

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

BACKEND = '''
import mido.ports

PORTS = {}          # port name -> messages waiting


def get_devices(**kwargs):
    return [{"name": n, "is_input": True, "is_output": True} for n in ("Loop", "Other")]


class Input(mido.ports.BaseInput):
    def _open(self, **kwargs):
        PORTS.setdefault(self.name, [])

    def _receive(self, block=True):
        waiting = PORTS[self.name]
        while waiting:
            self._messages.append(waiting.pop(0))


class Output(mido.ports.BaseOutput):
    def _open(self, **kwargs):
        PORTS.setdefault(self.name, [])

    def _send(self, message):
        PORTS[self.name].append(message)
'''


@pytest.fixture
def backend(tmp_path, monkeypatch):
    (tmp_path / "loopmidi.py").write_text(BACKEND)
    monkeypatch.syspath_prepend(str(tmp_path))
    yield
    sys.modules.pop("loopmidi", None)


def ports():
    return sys.modules["loopmidi"].PORTS


def send(name, *messages):
    import mido
    ports()[name].extend(mido.Message.from_bytes(m) for m in messages)


def interface(attrs=""):
    return f'<module class="MidiInterface" name="M" backend="loopmidi" {attrs}/>'


def test_messages_in_latest_and_all_of_a_tick(tmp_path, backend):
    net = load(tmp_path, interface('inport="Other" max_messages="2"'))
    try:
        net.step()
        assert net.output("M.COUNT").tolist() == [0]
        send("Other", [144, 60, 100], [0xC0, 5], [0xF0, 1, 2, 3, 0xF7], [128, 60, 0])
        net.step()
        assert net.output("M.OUTPUT").tolist() == [128, 60, 0]
        assert net.output("M.MESSAGES").tolist() == [[144, 60, 100], [192, 5, 0]]
        assert net.output("M.COUNT").tolist() == [3]           # sysex is skipped
        net.step()
        assert net.output("M.OUTPUT").tolist() == [128, 60, 0]  # kept
        assert net.output("M.COUNT").tolist() == [0]
        assert net.output("M.MESSAGES").tolist() == [[0, 0, 0], [0, 0, 0]]
    finally:
        net.close()


def test_input_rows_are_sent_when_they_change(tmp_path, backend):
    (tmp_path / "in.txt").write_text("A/6\n144 60 100 0 0 0\n144 60 100 176 7 64\n"
                                     "128 60 0 176 7 64\n192 9 0 0 0 0\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="in.txt"/>' +
               interface('outport="1" inport="0"') +
               '<connection source="F.A" target="M.INPUT" delay="0"/>')
    try:
        sent = []
        for _ in range(4):
            net.step()
            sent.extend(m.bytes() for m in ports()["Other"])
            ports()["Other"].clear()
        assert sent == [[144, 60, 100], [176, 7, 64], [128, 60, 0], [192, 9]]
    finally:
        net.close()


def test_interface_loops_into_filter(tmp_path, backend):
    (tmp_path / "in.txt").write_text("A/3\n176 2 90\n144 40 127\n144 36 10\n176 9 1\n0 0 0\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="in.txt"/>' +
               interface('inport="Loop" outport="Loop"') +
               '<module class="MidiFilter" name="Filter" filter="176 0 8; 144 36 52"/>'
               '<connection source="F.A" target="M.INPUT" delay="0"/>'
               '<connection source="M.MESSAGES" target="Filter.INPUT" delay="0"/>')
    try:
        assert net.output("Filter.OUTPUT1").shape == (8,)
        assert net.output("Filter.OUTPUT2").shape == (16,)
        net.run(ticks=6)           # a message sent on tick n is read on tick n + 1
        expected1 = np.zeros(8)
        expected1[2] = 90                      # controller 9 is out of range 0..7
        expected2 = np.zeros(16)
        expected2[4], expected2[0] = 127, 10
        assert net.output("Filter.OUTPUT1").tolist() == expected1.tolist()
        assert net.output("Filter.OUTPUT2").tolist() == expected2.tolist()
    finally:
        net.close()


def test_filter_table_and_latest_values(tmp_path):
    (tmp_path / "in.txt").write_text("A/3\n176 3 20\n177 3 99\n176 3 25\n0 3 50\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="in.txt"/>'
                         '<module class="MidiFilter" name="Filter" filter="176 2 5"/>'
                         '<connection source="F.A" target="Filter.INPUT" delay="0"/>')
    try:
        values = []
        for _ in range(4):
            net.step()
            values.append(net.output("Filter.OUTPUT1").tolist())
        assert values == [[0, 20, 0], [0, 20, 0], [0, 25, 0], [0, 25, 0]]
    finally:
        net.close()


def test_the_default_filter_row_gives_one_element(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="144 1 2"/>'
                         '<module class="MidiFilter" name="Filter"/>'
                         '<connection source="C.OUTPUT" target="Filter.INPUT"/>')
    try:
        net.run(ticks=2)
        assert net.output("Filter.OUTPUT1").tolist() == [0]
    finally:
        net.close()


def test_bad_filter_and_missing_port_are_load_errors(tmp_path, backend):
    with pytest.raises(ModelError, match="three columns"):
        load(tmp_path, '<module class="Constant" name="C" data="144 1 2"/>'
                       '<module class="MidiFilter" name="Filter" filter="1 2"/>'
                       '<connection source="C.OUTPUT" target="Filter.INPUT"/>')
    with pytest.raises(ModelError, match='no MIDI input named "Piano".*0: Loop, 1: Other'):
        load(tmp_path, interface('inport="Piano"'))
    with pytest.raises(ModelError, match="no MIDI input number 5"):
        load(tmp_path, interface('inport="5"'))
    with pytest.raises(ModelError, match='backend "no_such_backend" cannot be loaded'):
        load(tmp_path, '<module class="MidiInterface" name="M" backend="no_such_backend"/>')
