"""SequenceRecorder: records and plays back sequences of any values (Ikaros 2 and Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Output, Parameter
from ikaros.modules.robot._recording import Recorder

V3_OUTPUTS = {"PLAYING": "max_sequences", "COMPLETED": "max_sequences", "COLOR": "max_sequences",
              "LIMITING": 1, "ERROR": 1, "SMOOTHING_START": "channels", "TARGET": "channels",
              "OUTPUT": "channels", "ACTIVE": "channels", "CAN_PLAY": "channels"}


class SequenceRecorder(Recorder):
    """Records and plays back sequences of values, as Ikaros 2 and as Ikaros 3 do; the file's
    version decides which.

    In an Ikaros 2 file it is MotionRecorder for any sequence of ``output_size`` values: it
    records INPUT (its first ``output_size`` elements, zero-padded), or, when INPUT is not
    connected, the values set with the ``set`` command (value: the list of values) starting
    from ``positions``, so a sequence of keyframes can be built without a robot. Everything
    else — modes, TRIG, keyframes, interpolation (linear or smooth), smoothing, save and load,
    and the outputs COMPLETED (max_motions), TRIG_OUT, MODE, STATE, TIME, TORQUE, ENABLE,
    KEYPOINTS, TIMESTAMPS, LENGTHS — is as in MotionRecorder.

    In an Ikaros 3 file it has Ikaros 3's interface: ``channels`` values (INPUT, required),
    up to ``max_sequences`` sequences of keyframes, each channel with its own keyframes (time in
    seconds, value). ``state`` is one-hot over stop, play, record, pause, off (the state at
    the start; then the commands of those names, or a rising edge of TRIG element i, lower
    indices first, which plays sequence i from its start). ``channel_mode`` per channel: 0
    play (the sequence drives it, also while other channels record), 1 record (recorded from
    INPUT while recording, OUTPUT following INPUT; played while playing), 2 follow (OUTPUT is
    INPUT), 3 off (OUTPUT is ``default_output``); in the state off every channel follows.
    Playing moves the play head (``position``, seconds; ``time`` and ``end_time`` show it and
    the end as MM:SS:mmm) from ``mark_start`` to ``mark_end`` (or over the whole sequence when
    mark_end is not after mark_start); a channel's value there (TARGET) is its keyframes'
    (``interpolation`` per channel: 0 the earlier keyframe's value, 1 a straight line),
    clipped to ``range_min``..``range_max``. OUTPUT goes from where it was when playing began
    (SMOOTHING_START) to the target over ``smoothing_time`` seconds, and moves at most
    ``max_speed`` per second per channel (0 or none: no limit; LIMITING is 1 while a channel is
    held back). At the end COMPLETED pulses for the sequence, and it stops or, with ``loop``,
    begins again (with ``shuffle`` with a random sequence that has keyframes). Recording takes
    INPUT every tick from the play head on; when it stops, the stretch recorded replaces what
    the recording channels held there, simplified (Ramer-Douglas-Peucker: no value moves more
    than ``simplify_epsilon``). PLAYING is 1 for the sequence playing, ACTIVE 1 for the
    channels the sequence drives now, CAN_PLAY 1 for those the current sequence
    (``current_sequence``) has keyframes for, COLOR each sequence's colour (``color``, else a
    palette) for the web UI, whose buttons ``layout_width`` sets out; ERROR is 1 after a
    command that failed (with a warning) until one succeeds. The sequences (``sequence_names``)
    are kept in ``directory``/``filename`` as JSON ({"sequences": [{"name", "channels": [[[t,
    v], ...] per channel]}]}), read at the start when it exists, or one per file in
    ``file_names``. Commands: stop, play, record, pause, off, select (x: the sequence), seek
    (x: seconds), mark_start, mark_end (x, or the play head), keyframe (the recording channels'
    INPUT at the play head), clear, new (value: a name), save, load. This project's reading:
    Ikaros 3 gives the interface and the defaults, and that time is in seconds, sequences are
    JSON, interpolation, speed limits and simplification are per channel and TRIG selects the
    sequence; the states, channel modes, file layout and the rest are this project's."""

    positions = Parameter("", "Ikaros 2: the values recorded when INPUT is not connected, until changed with set; "
                          "Ikaros 3: per channel, kept", type="array", default_v3="0, 0, 0, 0")
    output_size = Parameter(1, "Ikaros 2: number of channels")
    directory = Parameter("motions", "folder of the files, relative to the model file", default_v3="Sequences")
    filename = Parameter("motion.%02d.dat", "Ikaros 2: file name of a motion, %02d its number; Ikaros 3: the "
                         "JSON file of the sequences", default_v3="sequence.json")
    interpolation = Parameter("linear", "Ikaros 2: linear or smooth (ease in and out); Ikaros 3: per channel, "
                              "0 step or 1 linear", type="string", default_v3="1, 1, 1, 1")

    max_sequences = Parameter(64, "Ikaros 3: how many sequences", type="int", range=(1, None))
    layout_width = Parameter(8, "Ikaros 3: sequence buttons in a row of the web UI", type="int")
    color = Parameter("", "Ikaros 3: each sequence's colour, a row of red, green, blue in 0..1", type="matrix")
    smoothing_time = Parameter(1.0, "Ikaros 3: seconds over which OUTPUT goes over to a sequence that begins")
    max_speed = Parameter("", "Ikaros 3: per channel, the most OUTPUT moves a second (0: no limit)", type="array")
    simplify_epsilon = Parameter(1.0, "Ikaros 3: the most a value may move when a recording is simplified")
    state_ = Parameter("1, 0, 0, 0, 0", "Ikaros 3: the state at the start, one-hot: stop, play, record, pause, off",
                       type="array", name="state")
    channel_mode = Parameter("0, 0, 0, 0", "Ikaros 3: per channel, 0 play, 1 record, 2 follow INPUT, 3 off",
                             type="array")
    range_min = Parameter("0, 0, 0, 0", "Ikaros 3: per channel, the lowest value", type="array")
    range_max = Parameter("1, 1, 1, 1", "Ikaros 3: per channel, the highest value", type="array")
    time = Parameter("00:00:000", "Ikaros 3: the play head as MM:SS:mmm")
    end_time = Parameter("00:00:000", "Ikaros 3: the end of the sequence as MM:SS:mmm")
    position = Parameter(0.0, "Ikaros 3: the play head (seconds)")
    mark_start = Parameter(0.0, "Ikaros 3: where playing begins (seconds)")
    mark_end = Parameter(0.0, "Ikaros 3: where playing ends (seconds; not after mark_start: the end)")
    shuffle = Parameter(False, "Ikaros 3: with loop, go on with a random sequence")
    channels = Parameter(4, "Ikaros 3: number of channels", type="int", range=(1, None))
    default_output = Parameter("0, 0, 0, 0", "Ikaros 3: per channel, OUTPUT at the start and when off", type="array")
    internal_control = Parameter("0, 0, 0, 0", "Ikaros 3: per channel (kept; the channel modes say who drives)",
                                 type="array")
    current_sequence = Parameter(0, "Ikaros 3: the sequence recorded, played and edited", type="int")
    sequence_names = Parameter("Sequence A", "Ikaros 3: the names of the sequences, comma-separated")
    file_names = Parameter("", "Ikaros 3: one file a sequence, comma-separated (empty: all in filename)")

    INPUT = Input("the values to record (Ikaros 2: optional)", optional=True)

    COMPLETED = Output("1 on the tick motion (Ikaros 3: sequence) i finishes playing")
    OUTPUT = Output("the values: recorded while recording, the sequence while playing")
    PLAYING = Output("Ikaros 3: 1 for the sequence playing")
    COLOR = Output("Ikaros 3: each sequence's colour (red, green, blue)")
    LIMITING = Output("Ikaros 3: 1 while max_speed holds a channel back")
    ERROR = Output("Ikaros 3: 1 after a command that failed")
    SMOOTHING_START = Output("Ikaros 3: OUTPUT when playing began")
    TARGET = Output("Ikaros 3: the sequence's values at the play head")
    ACTIVE = Output("Ikaros 3: 1 for the channels the sequence drives now")
    CAN_PLAY = Output("Ikaros 3: 1 for the channels the current sequence has keyframes for")

    def channel_count(self):
        return int(self.channels) if self.dialect == "3" else int(self.output_size)

    def set_sizes(self):
        n, count = self.channel_count(), int(self.max_sequences)
        sizes = {"max_sequences": count, "channels": n, 1: 1}
        for name, rule in V3_OUTPUTS.items():
            self.set_output_shape(name, (count, 3) if name == "COLOR" else sizes[rule])
        if self.dialect != "3":
            self.set_output_shape("COMPLETED", int(self.max_motions))
        super().set_sizes()

    def init(self):
        self._player = None
        if self.dialect == "3":
            from ikaros.modules.robot._sequence_player import SequencePlayer
            if self.INPUT is None:
                raise ValueError("the input INPUT is not connected (required in an Ikaros 3 file)")
            self._player = SequencePlayer(self)
            return
        if self.interpolation not in ("linear", "smooth"):
            raise ValueError(f'interpolation is "{self.interpolation}"; in an Ikaros 2 file: linear or smooth')
        self._manual = np.zeros(int(self.output_size))
        positions = np.asarray(self.positions, dtype=np.float64).reshape(-1)[:self._manual.size]
        self._manual[:positions.size] = positions
        super().init()

    def tick(self):
        if self._player is not None:
            self._player.tick()
        else:
            super().tick()

    def command(self, name, x=0, y=0, value=None):
        if self._player is not None:
            self._player.command(name, x, value)
            return
        if name == "set":
            values = np.asarray(value if value is not None else [x], dtype=np.float64).reshape(-1)
            self._manual[:] = 0.0
            self._manual[:min(values.size, self._manual.size)] = values[:self._manual.size]
            return
        super().command(name, x, y, value)

    def source(self):
        if self.INPUT is None:
            return self._manual.copy()
        values = np.zeros(self._manual.size)
        flat = self.INPUT.reshape(-1)[:values.size]
        values[:flat.size] = flat
        return values
