"""The recorder for a file name: MCAP (ROS 2 messages) for ``.mcap``, else HDF5."""
from __future__ import annotations

from .mcap_recording import McapRecorder
from .recording import Recorder


MCAP_ONLY = ("images", "joint_states")


def open_recorder(net, filename: str, **options):
    """Record ``net`` into ``filename``: an MCAP file of ROS 2 messages when it ends in
    ``.mcap`` (McapRecorder), else an HDF5 file (Recorder); ``options`` as theirs (``images``
    and ``joint_states``, the ROS types of outputs, are for MCAP files only)."""
    if str(filename).lower().endswith(".mcap"):
        return McapRecorder(net, filename, **options)
    given = [k for k in MCAP_ONLY if options.pop(k, None)]
    if given:
        raise ValueError(f"{' and '.join(given)} choose ROS message types: they are for "
                         f"MCAP recordings (a file ending in .mcap), not {filename}")
    return Recorder(net, filename, **options)
