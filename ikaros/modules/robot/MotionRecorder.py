"""MotionRecorder: records servo motions moved by hand and plays them back."""
import numpy as np

from ikaros.module import Input
from ikaros.modules.robot._recording import Recorder


class MotionRecorder(Recorder):
    """Records and plays back motions of a robot. INPUT is the present position of the servos
    (e.g. a Dynamixel's FEEDBACK_PRESENT_POSITION); OUTPUT goes to their goal positions and
    TORQUE to their torque enable. Modes (mode_string at start, then the commands record,
    play, stop and off, or a rising edge of TRIG element i, which plays motion i): in
    *record* the current motion is cleared and INPUT sampled every ``sample_interval`` ticks
    with its time, while TORQUE is ``torque_on_record`` (0: the arm is limp and moved by hand)
    and OUTPUT follows INPUT, so nothing jumps when torque returns; in *play* the samples are
    interpolated (``linear``, or ``smooth`` ease-in-out for keyframes), low-pass filtered with
    ``smoothing`` starting from the present position, and COMPLETED[i] and TRIG_OUT pulse on
    the tick the motion ends (then the recorder stops holding the last position, or plays again
    with ``loop``); in *stop* OUTPUT holds the position it had and torque is on; *off* is
    torque off with OUTPUT following INPUT. The ``keypoint`` command adds the present position
    as a keyframe ``keypoint_time`` seconds after the previous one, ``clear`` empties the current
    motion, ``select`` (value or x) chooses it, and ``save``/``load`` write and read it as text
    (a header line, then one line per sample: time in ms and the channel values) in
    ``directory``/``filename``; files found there are loaded at start. MODE is one-hot
    (stop, record, play, off), STATE its number. Differences from Ikaros 2: MODE is one
    vector for all channels; sample_interval, keypoint_time, interpolation, smoothing, loop
    and load_at_start are additions."""

    INPUT = Input("the present positions of the servos")

    def channel_count(self):
        shape = self.input_shape("INPUT")
        return None if shape is None else int(np.prod(shape))

    def source(self):
        return self.INPUT.reshape(-1).astype(np.float64)
