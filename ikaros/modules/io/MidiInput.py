"""MidiInput: keys pressed on a MIDI controller (a keyboard, a Launchpad) as outputs."""
import time

from ikaros.hardware import DeviceError, midi
from ikaros.module import Module, Output, Parameter

RETRY_SECONDS = 1.0             # how often a missing source is looked for again
NOTE_ON, NOTE_OFF, CONTROL_CHANGE = 0x90, 0x80, 0xB0


class MidiInput(Module):
    """Reads the key presses of a MIDI controller (Ikaros 3's class, written here from its
    interface and the MIDI messages): every tick it takes the messages that came since the
    previous one (LAST_BATCH_COUNT of them). A Note On with a velocity above 0 is a press
    of key note; a Note Off, or a Note On with velocity 0, its release; a Control Change
    with a value above 0 is a press of key controller number, and value 0 its release (the
    buttons of a Launchpad). KEY is the last key pressed, GATE is 1 while any key is held,
    TRIG is 1 for ``trig_hold_ticks`` ticks from a tick with a press, and EVENT_COUNT counts
    the presses since the start. The source is the first MIDI input whose name contains
    ``source_name``, else input number ``source_index`` (from 0), else (-1 and no name) all
    inputs; ``source_name="sim:launchpad"`` is a simulated Launchpad X (see docs/robots.md).
    SOURCE_COUNT is the number of MIDI inputs there are and CONNECTED is 1 while the source
    is open; a source that is missing, or goes away, is looked for again every second, and
    the run goes on. Real ports need mido and python-rtmidi (``pip install
    'ikaros[midi]'``)."""

    source_name = Parameter("", "the MIDI input whose name contains this (sim:launchpad: the "
                            "simulated Launchpad X); empty: by source_index")
    source_index = Parameter(-1, "the number of the MIDI input (from 0) when source_name is "
                             "empty; -1: all inputs", type="int", range=(-1, None))
    trig_hold_ticks = Parameter(1, "ticks TRIG stays 1 after a press", type="int",
                                range=(1, None))
    KEY = Output("the last key pressed (note or controller number)", size="1")
    GATE = Output("1 while any key is held", size="1")
    TRIG = Output("1 for trig_hold_ticks ticks from a press", size="1")
    EVENT_COUNT = Output("the number of presses since the start", size="1")
    SOURCE_COUNT = Output("the number of MIDI inputs", size="1")
    CONNECTED = Output("1 while the source is open", size="1")
    LAST_BATCH_COUNT = Output("the number of messages taken on this tick", size="1")

    def configure(self):
        midi.require_ports(self.source_name)

    def init(self):
        self._ports: list[midi.Port] = []
        self._held: set[int] = set()
        self._trig_left = 0
        self._next_try = 0.0
        self._connect()

    def _connect(self):
        self._next_try = time.monotonic() + RETRY_SECONDS
        self._ports = midi.open_wanted(self.source_name, False, self.source_index,
                                       self._warn)
        self.SOURCE_COUNT[0] = len(midi.port_names(output=False))
        self.CONNECTED[0] = float(bool(self._ports))

    def _warn(self, message: str):
        self.warning(f"{message}; trying again every {RETRY_SECONDS:g} s")

    def tick(self):
        if not self._ports and time.monotonic() >= self._next_try:
            self._connect()
        messages = []
        for port in list(self._ports):
            try:
                messages += port.pending()
            except DeviceError as e:
                self._warn(str(e))
                port.close()
                self._ports.remove(port)
        self.CONNECTED[0] = float(bool(self._ports))
        self.LAST_BATCH_COUNT[0] = len(messages)
        pressed = False
        for message in messages:
            pressed |= self._take(message)
        self.GATE[0] = float(bool(self._held))
        if pressed:
            self._trig_left = self.trig_hold_ticks
        self.TRIG[0] = float(self._trig_left > 0)
        self._trig_left = max(0, self._trig_left - 1)

    def _take(self, message: bytes) -> bool:
        """Note a message; True for a press."""
        if len(message) != 3:
            return False
        kind, key, value = message[0] & 0xF0, message[1], message[2]
        if kind in (NOTE_ON, CONTROL_CHANGE) and value > 0:
            self._held.add(key)
            self.KEY[0] = key
            self.EVENT_COUNT[0] += 1
            return True
        if kind in (NOTE_ON, NOTE_OFF, CONTROL_CHANGE):
            self._held.discard(key)
        return False

    def stop(self):
        for port in getattr(self, "_ports", []):
            port.close()
        self._ports = []
