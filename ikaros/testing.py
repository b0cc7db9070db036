"""Helpers for testing modules and models with pytest."""
from __future__ import annotations

import os
import time
from typing import Callable, Iterable

import numpy as np

from .kernel.network import Network
from .network import load


def load_body(folder, body: str, /, **overrides) -> Network:
    """Write ``body`` (module and connection elements) inside ``<group name="Test">`` to
    ``folder/model.ikg`` and load it; keyword arguments override top-group attributes::

        net = load_body(tmp_path, '<module class="Constant" name="C" data="1 2"/>')
    """
    path = os.path.join(str(folder), "model.ikg")
    with open(path, "w", encoding="utf-8") as f:
        f.write(f'<group name="Test">\n{body}\n</group>\n')
    return load(path, **overrides)


def matrix_text(a, spec: str = "") -> str:
    """``a`` as the text of a data attribute: rows separated by "; " and the elements of a
    row by spaces, each written as ``format(float(v), spec)`` (the default writes the float's
    repr); a 1-D ``a`` is one row and each row is flattened::

        matrix_text([[1, 2], [3, 4]]) == "1.0 2.0; 3.0 4.0"
        matrix_text([0.5, 2], "g") == "0.5 2"
    """
    return "; ".join(" ".join(format(float(v), spec) for v in np.ravel(row))
                     for row in np.atleast_2d(a))


def step_until(nets: Network | Iterable[Network], condition: Callable[[], bool], /,
               seconds: float = 5.0, pause: float = 0.002) -> None:
    """Step the network (or every network of a list) until ``condition()`` holds, pausing
    ``pause`` seconds between steps for a device, socket or thread to answer; fail with an
    AssertionError after ``seconds``."""
    nets = [nets] if isinstance(nets, Network) else list(nets)
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, f"timed out after {seconds} s"
        for net in nets:
            net.step()
        if pause:
            time.sleep(pause)


def wait_for(condition: Callable[[], object], seconds: float = 2.0,
             pause: float = 0.005) -> bool:
    """Whether ``condition()`` holds within ``seconds``, asking every ``pause`` seconds (for
    what a device, a simulator or another thread does in its own time)."""
    deadline = time.monotonic() + seconds
    while True:
        if condition():
            return True
        if time.monotonic() >= deadline:
            return False
        time.sleep(pause)


def running_processes(group: int | None = None, parent: int | None = None) -> list[int]:
    """The ids of the processes, zombies left out, of process group ``group`` and/or whose
    parent is ``parent`` (Linux: read from /proc), to check that a run left none behind."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", encoding="ascii", errors="replace") as f:
                state, ppid, pgrp = f.read().rsplit(")", 1)[1].split()[:3]
        except (OSError, ValueError):
            continue
        if state != "Z" and (group is None or int(pgrp) == group) and \
                (parent is None or int(ppid) == parent):
            found.append(int(entry))
    return found


# Examples whose values differ from run to run whatever the kernel does: servos of a
# simulator that move in real time, and OpenCV's float filters, which round the last bit
# differently from run to run (docs/images.md) and so may tip a threshold.
# robots and sensors whose simulators move or stream in real time
_NOT_REPEATABLE = {"epi.ikg", "lucs_arm.ikg", "arm_playback.ikg", "UM7_example.ikg"}


def repeatable_examples(root: str) -> list[str]:
    """The example models below ``root/examples`` that give the same values on every run
    (for tests that compare two runs tick by tick)."""
    import glob
    return sorted(p for p in glob.glob(os.path.join(root, "examples", "**", "*.ikg"),
                                       recursive=True)
                  if os.path.basename(p) not in _NOT_REPEATABLE
                  and os.path.basename(os.path.dirname(p)) not in ("vision", "ros2"))
