"""The recorder for a file name: MCAP (ROS 2 messages) for ``.mcap``, else HDF5."""
from __future__ import annotations

from .mcap_recording import McapRecorder
from .recording import Recorder


def open_recorder(net, filename: str, **options):
    """Record ``net`` into ``filename``: an MCAP file of ROS 2 messages when it ends in
    ``.mcap`` (McapRecorder), else an HDF5 file (Recorder); ``options`` as theirs."""
    kind = McapRecorder if str(filename).lower().endswith(".mcap") else Recorder
    return kind(net, filename, **options)
