"""A finished run shown again: the recorded model with every recorded module replaced by a
Replay of its outputs (``ikaros --replay run.h5``)."""
from __future__ import annotations

import os

from .reading import open_file

DROPPED = ("connection", "input")       # nothing is computed, so nothing flows in


def replay_network(filename: str, quiet: bool = True):
    """Build the model stored in a recording with each module whose outputs were recorded
    replaced by a ``Replay`` module of the same name and outputs (modules with no recorded
    output, connections and group inputs are left out; groups, group outputs and views
    stay). Tick k of the network shows the k-th recorded row; ``command(path, "seek", x)``
    moves a Replay module to another row. Nothing of the original classes runs, so a
    recording of a robot replays without its devices."""
    from ..kernel.builder import Builder
    from ..language.diagnostics import Diagnostics
    from ..language.reader import read_file
    path = os.path.abspath(filename)
    with open_file(path) as f:
        model_file = f.header["model_file"] or os.path.join(os.path.dirname(path),
                                                             "recorded.ikg")
        model = f.model
        modules = {name.rsplit(".", 1)[0] for name, *_ in f.signals}
    tree = read_file(model_file, model, root_tag="group")
    tree.attrs.pop("stop", None)
    _replace(tree, "", modules, path)
    net = Builder(model_file, {}, model=tree, diagnostics=Diagnostics(quiet=quiet)).build()
    net.replayed = path
    return net


def _replace(group, prefix: str, recorded: set, recording: str) -> None:
    kept = []
    for child in group.children:
        if child.tag in DROPPED:
            continue
        name = child.attrs.get("name") or child.attrs.get("class", "")
        address = prefix + name
        if child.tag == "module":
            if address not in recorded:
                continue
            child.attrs = {"class": "Replay", "name": name, "filename": recording,
                           "module": address, "signal": "", "end": "hold"}
            child.children = []
        elif child.tag == "group":
            _replace(child, address + ".", recorded, recording)
        elif child.children:        # an include: its elements are in this group
            _replace(child, prefix, recorded, recording)
        kept.append(child)
    group.children = kept
