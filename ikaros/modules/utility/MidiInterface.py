"""MidiInterface: MIDI in and out through mido (python-rtmidi: ALSA, JACK, CoreMIDI)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require


class MidiInterface(Module):
    """Reads and writes MIDI through mido (``pip install 'ikaros[midi]'``, which brings
    python-rtmidi for ALSA, JACK, CoreMIDI and Windows MM). OUTPUT is the latest incoming
    message as (status, data 1, data 2), e.g. (144, 60, 100) for note 60 on channel 1 at
    velocity 100, kept until the next one (a two-byte message has data 2 = 0; system
    exclusive messages are skipped). MESSAGES holds every message of this tick, one row each
    in arrival order (up to ``max_messages``, the rest of the rows 0), and COUNT how many
    came, so that no message is lost on a busy tick.

    INPUT, when connected, is sent: its elements taken three at a time as (status, data 1,
    data 2) messages; a message goes out when its row changes and its status is 128 or more
    (a row of 0s sends nothing). ``inport`` and ``outport`` choose the ports: a number
    (the index in the backend's list) or a port name. With ``virtual`` the module opens
    virtual ports of that name that other programs connect to (ALSA, JACK, CoreMIDI; not on
    Windows). ``backend`` is a mido backend module (mido.backends.rtmidi by default). A
    missing port is a load error that lists the ports there are. ``debug`` prints every
    message. Unlike Ikaros 2 (RtMidi compiled in), ports can be named and made virtual, and
    MESSAGES and COUNT are new."""

    inport = Parameter("0", "the input port: its number in the backend's list, or its name")
    outport = Parameter("0", "the output port: its number, or its name (used only when "
                        "INPUT is connected)")
    virtual = Parameter("", "when set, open virtual ports of this name instead")
    backend = Parameter("mido.backends.rtmidi", "the mido backend module")
    max_messages = Parameter(16, "rows of MESSAGES: the most messages kept per tick",
                             type="int")
    debug = Parameter(False, "print every message received and sent")

    INPUT = Input("messages to send: (status, data 1, data 2) rows", optional=True)
    OUTPUT = Output("the latest message received: (status, data 1, data 2)", size=3)
    MESSAGES = Output("the messages of this tick, one (status, data 1, data 2) row each "
                      "(max_messages rows)")
    COUNT = Output("how many messages came this tick", size=1)

    def configure(self):
        self._mido = require("mido", "mido", extra="midi")
        if self.max_messages < 1:
            raise ValueError(f"max_messages={self.max_messages} must be 1 or more")
        self.set_output_shape("MESSAGES", (self.max_messages, 3))

    def init(self):
        try:
            self._backend = self._mido.Backend(self.backend, load=True)
        except ImportError as e:
            raise ValueError(f'the MIDI backend "{self.backend}" cannot be loaded ({e}): '
                             f"pip install 'ikaros[midi]'") from None
        self._in = self._open("input", self.inport)
        self._out = self._open("output", self.outport) if self.INPUT is not None else None
        self._sent = np.zeros((0, 3), np.float32)

    def _open(self, kind, which):
        backend = self._backend
        try:
            if self.virtual:
                opener = backend.open_input if kind == "input" else backend.open_output
                return opener(self.virtual, virtual=True)
            names = (backend.get_input_names() if kind == "input"
                     else backend.get_output_names())
            name = str(which).strip()
            if name.isdigit():
                if int(name) >= len(names):
                    raise ValueError(f"there is no MIDI {kind} number {name}")
                name = names[int(name)]
            elif name not in names:
                raise ValueError(f'there is no MIDI {kind} named "{name}"')
            return (backend.open_input if kind == "input" else backend.open_output)(name)
        except (OSError, SystemError, RuntimeError, ValueError) as e:
            listing = ", ".join(f"{k}: {n}" for k, n in enumerate(
                self._names(kind))) or "none"
            raise ValueError(f"cannot open the MIDI {kind} ({e}); the {kind}s are: "
                             f"{listing}") from None

    def _names(self, kind):
        try:
            return (self._backend.get_input_names() if kind == "input"
                    else self._backend.get_output_names())
        except Exception:       # the backend itself does not work here
            return []

    def tick(self):
        self.MESSAGES.fill(0)
        count = 0
        for message in self._in.iter_pending():
            data = message.bytes()
            if len(data) > 3 or not data:
                continue
            if self.debug:
                self.print(f"received {data}")
            row = (data + [0, 0])[:3]
            self.OUTPUT[:] = row
            if count < self.MESSAGES.shape[0]:
                self.MESSAGES[count] = row
            count += 1
        self.COUNT[0] = count
        if self._out is not None:
            self._send()

    def _send(self):
        rows = self.INPUT.reshape(-1)[:self.INPUT.size // 3 * 3].reshape(-1, 3)
        if self._sent.shape != rows.shape:
            self._sent = np.zeros_like(rows)
        for k in np.flatnonzero((rows != self._sent).any(axis=1) & (rows[:, 0] >= 128)):
            data = [int(v) & 0xFF if i == 0 else int(v) & 0x7F
                    for i, v in enumerate(rows[k])]
            message = self._message(data)
            if message is not None:
                if self.debug:
                    self.print(f"sent {message.bytes()}")
                self._out.send(message)
        self._sent[...] = rows

    def _message(self, data):
        """The message of a row: three bytes, or the first two for a two-byte status."""
        for n in (3, 2, 1):
            try:
                return self._mido.Message.from_bytes(data[:n])
            except ValueError:
                continue
        self.warning(f"{data} is not a MIDI message; not sent")
        return None

    def stop(self):
        for port in (self._in, self._out):
            if port is not None:
                port.close()
