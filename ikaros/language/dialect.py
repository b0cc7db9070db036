"""Which Ikaros a model file was written for: "2" (the default) or "3".

A top-group ``dialect`` attribute (or a load-time override, ``ikaros --dialect``) says it
outright. Without one (docs/language.md, "Ikaros 2 and Ikaros 3 files"):

1. a form that only Ikaros 3 reads makes it an Ikaros 3 file (``ikaros3_form``);
2. otherwise its signs decide: names that only one version has (classes, parameters, ports,
   option labels: ``vocabulary.py``), forms that only one version reads (a group port without
   an alias, a connection label, ``flatten`` / ``stack`` flags; aliases, offsets, views,
   renamings, delay lists, matrices written with spaces), a class file of Ikaros 3 beside it,
   top-group settings that Ikaros 3 reads (``stop``, ``tick_duration``, ...). Signs of
   Ikaros 3 and none of Ikaros 2 make it an Ikaros 3 file; anything else is an Ikaros 2 file.
   The weak signs of Ikaros 3 (in the interface of a class both have, and the top-group
   settings: this project's Ikaros 2 files use them as well) never outweigh a sign of
   Ikaros 2. When signs chose Ikaros 3, or strong signs point both ways, ``Reading.reason``
   says in one line what was chosen and why.
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass

from ..errors import ModelError
from .node import Node
from .reader import read_file
from .vocabulary import (IKAROS2_CLASSES, IKAROS2_PORTS, IKAROS3_CLASSES, IKAROS3_LABELS,
                         IKAROS3_PARAMETERS, IKAROS3_PORTS)

DIALECTS = ("2", "3")

# Top-group settings that only Ikaros 3 reads (FORMATS §2.2; Ikaros 2 spells the checksum
# "checksum" and takes the rest as command-line options, if at all)
IKAROS3_SETTINGS = frozenset((
    "check_sum", "real_time", "start", "load_state", "save_state", "webui_port",
    "webui_req_int", "snapshot_interval", "rgb_quality", "gray_quality",
    "webui_log_buffer_limit"))

# Top-group settings that Ikaros 3 reads and Ikaros 2 takes from its command line: signs of
# Ikaros 3 that this project's own Ikaros 2 files use as well, so they never outweigh a sign
# of Ikaros 2
IKAROS3_RUN_SETTINGS = ("stop", "tick_duration", "threads", "task_timeout", "log_level")

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
# a matrix written with spaces between its numbers, which Ikaros 3 does not split
_SPACED = re.compile(rf"\s*{_NUMBER}(?:\s+{_NUMBER})+\s*(?:;\s*{_NUMBER}(?:\s+{_NUMBER})*\s*)*"
                     rf";?\s*$")
_PORT_FLAGS = ("flatten", "stack", "use_label")


@dataclass(frozen=True)
class Sign:
    """Something in a file that only one version of Ikaros reads."""
    version: str
    text: str
    node: Node
    # a sign of Ikaros 3 in the interface of a class both versions have (a parameter, a port,
    # an option label), or a top-group setting, is weak: this project's Ikaros 2 files use
    # them too (its classes take both interfaces), so alone it does not decide
    strong: bool = True

    def where(self) -> str:
        return f"{self.text} (line {self.node.line})" if self.node.line else self.text


@dataclass(frozen=True)
class Reading:
    """The dialect a file is read in; ``reason`` says why when signs chose it or disagreed."""
    dialect: str
    reason: str | None = None


def detect_dialect(top: Node, folder: str | None = None) -> str:
    """"3" when the file (its includes spliced in) was written for Ikaros 3, else "2";
    ``folder`` is where the file lies (for the class files beside it)."""
    return read_dialect(top, folder).dialect


def read_dialect(top: Node, folder: str | None = None) -> Reading:
    """The dialect of a file without a ``dialect`` attribute, and why (see the module)."""
    nodes = _walk(top)
    if _first_form(top, nodes) is not None:
        return Reading("3")
    signs = _signs(top, nodes, folder)
    v3 = [s for s in signs if s.version == "3"]
    v2 = [s for s in signs if s.version == "2"]
    strong = [s for s in v3 if s.strong]
    if not v3 or (v2 and not strong):
        return Reading("2")
    if v2:
        return Reading("2", f"read as an Ikaros 2 file: {v2[0].where()} is Ikaros 2's, "
                            f"although {strong[0].where()} is Ikaros 3's; write "
                            f'dialect="3" on the top group to read it as Ikaros 3')
    sign = (strong or v3)[0]
    return Reading("3", f"read as an Ikaros 3 file: {sign.where()} is Ikaros 3's and nothing "
                        f'in it is only Ikaros 2\'s; write dialect="2" on the top group to '
                        f"read it as Ikaros 2")


def ikaros3_form(top: Node) -> str | None:
    """A short description of the first Ikaros 3-only form in the file, or None."""
    return _first_form(top, _walk(top))


def _first_form(top: Node, nodes: list) -> str | None:
    for key in top.attrs:
        if key in IKAROS3_SETTINGS:
            return f'the top-group setting "{key}"'
    for node, _ in nodes:
        # (a connection's form is a bracketed delay)
        if node.tag in _FORM_TAGS and (node.tag != "connection" or
                                       "[" in node.attrs.get("delay", "")):
            found = _form(node)
            if found is not None:
                return found
    return None


_FORM_TAGS = frozenset(("widget", "group", "connection"))


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


def _signs(top: Node, nodes: list, folder: str | None) -> list[Sign]:
    """Every sign of either version in the file (``nodes``: _walk's), in document order."""
    signs = [Sign("3", f'the top-group setting "{key}"', top, strong=False)
             for key in IKAROS3_RUN_SETTINGS if key in top.attrs]
    if "checksum" in top.attrs:
        signs.append(Sign("2", 'the top-group "checksum"', top))
    classes: dict[str, str | None] = {}       # module name -> class (None: ambiguous)
    for node, _ in nodes:
        if node.tag == "module":
            name, cls = node.attrs.get("name"), node.attrs.get("class", "")
            if name is not None:
                classes[name] = cls if classes.get(name, cls) == cls else None
    # a connection's ports are looked at only when a class with ports of one version is used
    ported = any(cls in IKAROS3_PORTS or cls in IKAROS2_PORTS for cls in classes.values())
    profiles = _ClassProfiles(folder)
    for node, parent in nodes:
        tag, attrs = node.tag, node.attrs
        if tag == "module":
            _module_signs(node, profiles, signs)
        elif tag in ("input", "output") and parent.tag == "group":
            signs += _port_signs(node)
        elif tag == "connection":
            _connection_signs(node, classes if ported else None, signs)
        elif tag == "view":
            signs.append(Sign("2", "a <view> element", node))
        elif tag == "parameter" and parent.tag == "group" and attrs.get("target"):
            signs.append(Sign("2", "a renaming <parameter target>", node))
    return signs


def _walk(top: Node) -> list[tuple[Node, Node]]:
    """(element, its parent) of every element below ``top``, each element's children
    together, includes spliced in."""
    pairs = []
    stack = [top]
    while stack:
        node = stack.pop()
        children = list(node.elements())
        pairs += [(child, node) for child in children]
        stack += [child for child in reversed(children) if child.children]
    return pairs


@dataclass(frozen=True)
class _ClassProfile:
    """What a module element's class alone says, and which of its attributes may say more."""
    sign: str | None            # the version whose class it is only, if one
    parameters: frozenset       # Ikaros 3's parameters of the class
    labels: dict                # attribute -> Ikaros 3's option labels of the class
    ikaros3_file: bool          # an Ikaros 3 class file beside the model
    named: frozenset            # the attributes of either of the two before


class _ClassProfiles(dict):
    """The profile of each class, made when a module element first names it."""

    def __init__(self, folder: str | None):
        super().__init__()
        self.class_files = _ClassFiles(folder)

    def __missing__(self, cls: str) -> _ClassProfile:
        sign = "3" if cls in IKAROS3_CLASSES else "2" if cls in IKAROS2_CLASSES else None
        prefix = f"{cls}."
        labels = {key[len(prefix):]: values for key, values in IKAROS3_LABELS.items()
                  if key.startswith(prefix)}
        parameters = IKAROS3_PARAMETERS.get(cls, frozenset())
        profile = self[cls] = _ClassProfile(sign, parameters, labels,
                                            self.class_files.ikaros3(cls),
                                            parameters | labels.keys())
        return profile


_WHITESPACE = re.compile(r"\s")


def _module_signs(node: Node, profiles: _ClassProfiles, signs: list) -> None:
    attrs = node.attrs
    cls = attrs.get("class", "")
    profile = profiles[cls]
    if profile.sign is not None:
        signs.append(Sign(profile.sign, f'the class "{cls}"', node))
    # an attribute is a sign only when it is a parameter or option label of Ikaros 3, an
    # input flag (it has a dot) or a matrix with spaces (it has white space)
    values = "".join(attrs.values())
    if (profile.named.isdisjoint(attrs) and "." not in "".join(attrs)
            and (values.isalnum() or _WHITESPACE.search(values) is None)):
        if profile.ikaros3_file:
            signs.append(Sign("3", f'the Ikaros 3 class file "{cls}.ikc" beside it', node))
        return
    for key, value in attrs.items():
        if key in profile.parameters:
            signs.append(Sign("3", f'the parameter "{key}" of {cls}', node, strong=False))
        elif value in profile.labels.get(key, ()):
            signs.append(Sign("3", f'{key}="{value}" of {cls}', node, strong=False))
        elif key.rpartition(".")[2] in _PORT_FLAGS and "." in key:
            signs.append(Sign("3", f'the input flag "{key}"', node))
        elif _SPACED.match(value) and not key.startswith("_"):
            signs.append(Sign("2", f'the matrix {key}="{value}" written with spaces', node))
    if profile.ikaros3_file:
        signs.append(Sign("3", f'the Ikaros 3 class file "{cls}.ikc" beside it', node))


def _port_signs(node: Node) -> list[Sign]:
    attrs = node.attrs
    alias = "target" if node.tag == "input" else "source"
    if attrs.get(alias) or attrs.get(f"{alias}module"):
        return [Sign("2", f"a group {node.tag} alias ({alias}=)", node)]
    signs = [Sign("3", f'the group {node.tag} "{attrs.get("name")}" without {alias}=', node)]
    signs += [Sign("3", f'{key}= on a group input', node) for key in _PORT_FLAGS if key in attrs]
    return signs


_OFFSETS = frozenset(("sourceoffset", "targetoffset", "size"))


def _connection_signs(node: Node, classes: dict | None, signs: list) -> None:
    """The signs of a connection (``classes``: module name -> class, None when no class
    used has ports of only one version)."""
    attrs = node.attrs
    if "label" in attrs:
        signs.append(Sign("3", "a connection label", node))
    if not _OFFSETS.isdisjoint(attrs):
        signs.append(Sign("2", "a connection with sourceoffset/targetoffset/size", node))
    if "," in attrs.get("delay", ""):
        signs.append(Sign("2", f'the delay list "{attrs["delay"]}"', node))
    if classes is None:
        return
    for key in ("source", "target"):
        path, _, port = attrs.get(key, "").partition("[")[0].rpartition(".")
        cls = classes.get(path.rpartition(".")[2])
        if cls and port in IKAROS3_PORTS.get(cls, ()):
            signs.append(Sign("3", f'the port {port} of {cls}', node, strong=False))
        elif cls and port in IKAROS2_PORTS.get(cls, ()):
            signs.append(Sign("2", f'the port {port} of {cls}', node))


class _ClassFiles:
    """Whether a class file beside the model is written in Ikaros 3's forms."""

    def __init__(self, folder: str | None):
        self.folder = folder
        self.seen: dict[str, bool] = {}

    def ikaros3(self, cls: str) -> bool:
        if not self.folder or not cls or "@" in cls:
            return False
        if cls not in self.seen:
            self.seen[cls] = _ikaros3_class_file(os.path.join(self.folder, f"{cls}.ikc"))
        return self.seen[cls]


# Ikaros 3's forms and Ikaros 2's in a class file (FORMATS §3)
_IKC3_ATTRS = frozenset(("options", "control", "shape", "dynamic", "capacity", "alias",
                         "persistent", "flatten", "stack", "use_label", "python", "internal"))
_IKC2_ATTRS = frozenset(("values", "size_set", "size_set_x", "size_set_y", "size_param",
                         "size_param_x", "size_param_y", "size_x", "size_y",
                         "allow_multiple_connections"))


def _ikaros3_class_file(path: str) -> bool:
    if not os.path.isfile(path):
        return False
    try:
        root = read_file(path)
    except (ModelError, OSError):
        return False         # the build reports it, if the class is used
    v3, v2 = root.tag == "group", False         # a group as a class (Ikaros 3)
    for node in [root] + list(root.elements()):
        keys = set(node.attrs)
        v3 |= bool(keys & _IKC3_ATTRS) or node.tag == "state" or \
            node.attrs.get("type") in ("number", "rate")
        v2 |= bool(keys & _IKC2_ATTRS) or node.tag == "link" or \
            node.attrs.get("type") in ("float", "list")
    return v3 and not v2
