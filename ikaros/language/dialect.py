"""Which Ikaros a model file was written for: "2" (the default) or "3".

A top-group ``dialect`` attribute (or a load-time override, ``ikaros --dialect``) says it
outright. Without one, a file is Ikaros 3 when it uses a form that only Ikaros 3 reads
(docs/language.md, "Dialect"); nothing of the sort means Ikaros 2.
"""
from __future__ import annotations

from .node import Node

DIALECTS = ("2", "3")

# Top-group settings that only Ikaros 3 reads (FORMATS §2.2; Ikaros 2 spells the checksum
# "checksum" and takes the rest as command-line options, if at all)
IKAROS3_SETTINGS = frozenset((
    "check_sum", "real_time", "start", "load_state", "save_state", "webui_port",
    "webui_req_int", "snapshot_interval", "rgb_quality", "gray_quality",
    "webui_log_buffer_limit"))


def detect_dialect(top: Node) -> str:
    """"3" when the file (its includes spliced in) uses an Ikaros 3-only form, else "2"."""
    return "3" if ikaros3_form(top) is not None else "2"


def ikaros3_form(top: Node) -> str | None:
    """A short description of the first Ikaros 3-only form in the file, or None."""
    for key in top.attrs:
        if key in IKAROS3_SETTINGS:
            return f'the top-group setting "{key}"'
    stack = [top]
    while stack:
        node = stack.pop()
        for child in node.elements():
            found = _form(child)
            if found is not None:
                return found
            stack.append(child)
    return None


def _form(node: Node) -> str | None:
    tag = node.tag
    if tag == "widget":
        return "a <widget> element"
    if tag == "group" and node.attrs.get("external"):
        return "an external group"
    if tag == "connection":
        delay = node.attrs.get("delay", "")
        if delay.strip().startswith("["):
            return f'the bracketed delay "{delay}"'
    return None
