"""The experiment options of the ``ikaros`` command: recording and progress of a run."""
from __future__ import annotations

import argparse
import contextlib
import sys


def _every(text: str) -> int:
    if not text.lstrip("+").isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f'"{text}" is not a whole number of ticks >= 1')
    return int(text)


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not value >= 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f'"{text}" is not a number of seconds >= 0')
    return value


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Add --record, --record-only, --record-every, --record-flush, --record-on-error and
    --replay to the ikaros command."""
    g = p.add_argument_group("experiments")
    g.add_argument("--record", metavar="FILE.h5",
                   help="record outputs into an HDF5 file while running (needs "
                        "ikaros[record]); read it with ikaros.open_recording. A FILE.mcap "
                        "is an MCAP file of ROS 2 messages for Foxglove and ros2 bag (needs "
                        "ikaros[ros2])")
    g.add_argument("--record-only", action="append", metavar="PATTERN",
                   help="record only the outputs whose address matches this glob pattern, "
                        "e.g. 'Arm.*.OUTPUT' (repeatable; default: every output)")
    g.add_argument("--record-every", type=_every, default=1, metavar="K",
                   help="record every K-th tick (default 1: every tick)")
    g.add_argument("--record-images", action="append", metavar="PATTERN",
                   help="MCAP: record the gray (rows, cols) outputs matching this pattern "
                        "as sensor_msgs/Image (besides colour images and the gray images "
                        "the views show; repeatable)")
    g.add_argument("--record-joint-states", action="append", metavar="PATTERN",
                   help="MCAP: record the outputs matching this pattern as "
                        "sensor_msgs/JointState, in radians (repeatable)")
    g.add_argument("--foxglove", nargs="?", type=int, const=8765, metavar="PORT",
                   help="serve the outputs live to Foxglove on 127.0.0.1:PORT (default "
                        "8765) as ROS 2 messages (needs ikaros[foxglove])")
    g.add_argument("--record-flush", type=_seconds, default=None, metavar="SECONDS",
                   help="write and flush the recorded rows at least this often (default "
                        "1); a run killed with SIGKILL loses at most about this long; 0: "
                        "after every tick")
    g.add_argument("--record-on-error", choices=("stop", "continue"), default="stop",
                   help="when writing the recording fails (a full disk): stop the run "
                        "(default) or continue it without recording")
    g.add_argument("--replay", metavar="FILE.h5",
                   help="show a recording in the web UI: its model's views, stepping "
                        "through the recorded ticks")


def check_arguments(p: argparse.ArgumentParser, opts) -> None:
    """Usage errors of the experiment options."""
    if (opts.record_only or opts.record_every != 1 or opts.record_flush is not None or
            opts.record_on_error != "stop") and not opts.record:
        p.error("--record-only, --record-every, --record-flush and --record-on-error need "
                "--record FILE.h5")
    if (opts.record_images or opts.record_joint_states) and \
            not str(opts.record or "").lower().endswith(".mcap"):
        p.error("--record-images and --record-joint-states need --record FILE.mcap")


def start_live_view(net, opts):
    """The Foxglove view of --foxglove (None without it); it ends when the network closes.
    Raises ImportError or OSError with a message for the user."""
    if opts.foxglove is None:
        return None
    from .foxglove_live import FoxgloveView
    view = FoxgloveView(net, port=opts.foxglove)
    print(f"ikaros: Foxglove: ws://127.0.0.1:{view.port} ({len(view.channels)} outputs)",
          file=sys.stderr)
    return view


def start_recording(net, opts, argv: list[str]):
    """The Recorder of --record (None without it); it ends when the network closes.
    Raises ValueError, ImportError or OSError with a message for the user."""
    if not opts.record:
        return None
    from .recorders import open_recorder
    from .recording import FLUSH_SECONDS
    return open_recorder(net, opts.record, only=opts.record_only, every=opts.record_every,
                         images=opts.record_images or (),
                         joint_states=opts.record_joint_states or (),
                         command_line=["ikaros"] + list(argv),
                         flush_seconds=FLUSH_SECONDS if opts.record_flush is None
                         else opts.record_flush, on_error=opts.record_on_error)


@contextlib.contextmanager
def batch_session(net, opts, recording=None):
    """Around a batch run: the progress bar (on a terminal, not with -q); the recording
    is closed at the end (not marked finished when the run was interrupted)."""
    from .progress import Progress
    complete = False
    try:
        if Progress.wanted(sys.stderr, opts.quiet):
            total = opts.stop if opts.stop is not None else \
                net.stop_tick if (net.stop_tick or -1) >= 0 else None
            with Progress(net, total):
                yield
        else:
            yield
        complete = True
    except BaseException as e:      # a run ended by an error is recorded whole
        complete = not isinstance(e, KeyboardInterrupt)
        raise
    finally:
        if recording is not None:
            recording.close(complete=complete)
