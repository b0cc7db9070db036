"""The front-end objects of a model built in code: groups, modules, ports, connections and
views. Each one is a thin handle on an element of the same model tree a file gives
(``ikaros.language.node.Node``), so a model built in code is built, checked and saved exactly
as a file is. An element made in code records the Python file and line that made it, and
errors name them."""
from __future__ import annotations

import functools
import os
import sys
from types import FrameType
from typing import Any, Iterator, cast

from ..errors import ModelError
from ..language.node import Node
from ..language.values import value_text
from ..module import Module
from ..network import build_tree
from ..notebook import model_html

_HERE = os.path.dirname(os.path.abspath(__file__))


def caller() -> tuple[str | None, int | None]:
    """The file and line of the user's code that called into this package."""
    frame: FrameType | None = sys._getframe(1)
    while frame is not None and _is_ours(frame.f_code.co_filename):
        frame = frame.f_back
    if frame is None:
        return None, None
    return _where(frame.f_code.co_filename), frame.f_lineno


@functools.lru_cache(maxsize=256)
def _is_ours(file: str) -> bool:
    return os.path.dirname(os.path.abspath(file)) == _HERE


def _where(file: str) -> str:
    cell = _notebook_cell(file)
    if cell is not None:
        return cell
    return file if file.startswith("<") else _absolute(file)


@functools.lru_cache(maxsize=256)
def _absolute(file: str) -> str:
    return os.path.abspath(file)


def _notebook_cell(file: str) -> str | None:
    """How IPython names the cell that ``file`` stands for (``Cell In[3]``), if it is one."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    name = getattr(getattr(shell, "compile", None), "format_code_name", None)
    label = name(file) if name is not None else None
    return f"{label[0]} {label[1]}" if label else None


def _text(value: Any) -> str:
    if isinstance(value, Port):
        raise TypeError("a port is not an attribute value; connect it instead")
    return value_text(value)


def _node(tag: str, attrs: dict) -> Node:
    file, line = caller()
    return Node(tag, {k: _text(v) for k, v in attrs.items() if v is not None}, [], file, line)


class Element:
    """An element of the model: its attributes are those of the XML element."""

    def __init__(self, node: Node, parent: "Element | None"):
        self.node = node
        self.parent = parent

    @property
    def name(self) -> str | None:
        return self.node.attrs.get("name")

    @property
    def attrs(self) -> dict[str, str]:
        """The element's attributes as text, in order (changing it changes the model)."""
        return self.node.attrs

    def set(self, **attrs: Any) -> "Element":
        """Set attributes (parameters of a module, variables of a group); None removes one."""
        for key, value in attrs.items():
            if value is None:
                self.node.attrs.pop(key, None)
            else:
                self.node.attrs[key] = _text(value)
        return self

    def get(self, key: str, default: str | None = None) -> str | None:
        return self.node.attrs.get(key, default)

    def add(self, tag: str, /, **attrs: Any) -> "Element":
        """Add a child element of any kind: the ``<column>`` elements of an OutputCSV, a
        ``<data>`` table in a group, an Ikaros 3 element the API has no method for."""
        node = _node(tag, attrs)
        self.node.children.append(node)
        return Element(node, self)

    @property
    def children(self) -> list["Element"]:
        """The child elements (included elements spliced in, comments left out)."""
        return [Element(n, self) for n in self.node.elements()]

    def path(self) -> str:
        """The dotted path from the top group (without its name), as in the network."""
        names: list[str] = []
        element = self
        while element.parent is not None:
            names.append(element.name or "")
            element = element.parent
        return ".".join(reversed(names))

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.node.label()}>"


class Port:
    """An input or output of a module or group, with optional selectors:
    ``pid.OUTPUT``, ``pid.OUTPUT[0:2]``, ``image.OUTPUT[1:3, 0:4]``."""

    def __init__(self, owner: Element, name: str, selector: str = ""):
        self.owner = owner
        self.name = name
        self.selector = selector

    def __getitem__(self, key) -> "Port":
        keys = key if isinstance(key, tuple) else (key,)
        return Port(self.owner, self.name, self.selector + "".join(map(_selector, keys)))

    def address(self, seen_from: "Group") -> str:
        """The port as a connection in group ``seen_from`` names it."""
        if self.owner is seen_from:
            return self.name + self.selector
        names: list[str] = []
        element = self.owner
        while element is not seen_from:
            if element.parent is None:
                raise ModelError(f'{self} is not inside group "{seen_from.name}": connect it '
                                 f'in a group that holds both ends', *caller())
            names.append(element.name or "")
            element = element.parent
        return ".".join(reversed(names)) + "." + self.name + self.selector

    def __repr__(self) -> str:
        return f"<Port {self.owner.path() or self.owner.name}.{self.name}{self.selector}>"


def _selector(key) -> str:
    if isinstance(key, slice):
        if key.start is None and key.stop is None and key.step is None:
            return "[]"
        if key.start is None or key.stop is None:
            raise ValueError("a port selector range needs both bounds, as in [0:2]")
        step = "" if key.step in (None, 1) else f":{key.step}"
        return f"[{key.start}:{key.stop}{step}]"
    if isinstance(key, int):
        return f"[{key}]"
    raise TypeError(f"a port selector is a whole number or a range, not {key!r}")


class _Ports:
    """Ports as attributes: ``element.OUTPUT`` (``element.port("name")`` for a port whose
    name is also a method's)."""

    def __getattr__(self, name: str) -> Port:
        if name.startswith("_"):
            raise AttributeError(name)
        return Port(cast(Element, self), name)

    def port(self, name: str) -> Port:
        return Port(cast(Element, self), name)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._port_names()))

    def _port_names(self) -> list[str]:
        return []


class ModuleElement(_Ports, Element):
    """A module in a group: ``pid = model.module("PIDController", "PID", Kp=0.5)``; its ports
    are attributes (``pid.OUTPUT``)."""

    @property
    def class_name(self) -> str:
        return self.node.attrs.get("class", "")

    def _port_names(self) -> list[str]:
        """The ports its class declares (for completion in notebooks), when it is found."""
        from ..kernel.classes import ClassRegistry
        top = cast("Group", self.parent)._top() if self.parent is not None else None
        cls = top._classes.get(self.class_name) if top is not None else None
        try:
            if cls is None:
                folder = os.path.dirname(top.filename) if top is not None else os.getcwd()
                entry = ClassRegistry([folder]).find(self.class_name)
                if entry is None or entry.is_group:
                    return []
                cls = entry.module_class()
            desc = cls.description
        except (ModelError, ImportError):
            return []
        return [p.name for p in list(desc.inputs) + list(desc.outputs)]


class Connection(Element):
    """A connection; its attributes are ``source``, ``target``, ``delay`` ..."""


class View(Element):
    """A view of a group, holding widgets."""

    def widget(self, kind: str, **attrs: Any) -> Element:
        """Add a widget (``plot``, ``bar-graph``, ``image``, ``table`` ...). A port given as
        an attribute (``source=pid.OUTPUT``) is named as the view's group sees it."""
        group = cast("Group", self.parent)
        attrs = {k: (v.address(group) if isinstance(v, Port) else v) for k, v in attrs.items()}
        node = _node(kind, attrs)
        self.node.children.append(node)
        return Element(node, self)

    @property
    def widgets(self) -> list[Element]:
        return [Element(n, self) for n in self.node.elements()]


def _delay_text(delay) -> str | None:
    """A number of ticks, a ``range`` (half-open, as in Python), a list ``[0, 2]``, or the
    language's own text (``"1:3"``). A range or list is written as a list of its delays
    (``range(1, 4)`` as ``1, 2, 3``), which every file reads alike: ``1:3`` is 1, 2 in an
    Ikaros 3 file, and a bracketed ``[1:4]`` would make the model an Ikaros 3 file."""
    if delay is None or isinstance(delay, str):
        return delay
    if isinstance(delay, range):
        if len(delay) == 0:
            raise ValueError(f"{delay} holds no delay")
        delay = list(delay)
    if isinstance(delay, (list, tuple)):
        return ", ".join(value_text(int(d)) for d in delay)
    return value_text(delay)


class Group(_Ports, Element):
    """A group of modules, groups and connections; the top group is the model.

        model = ikaros.Group("Arm", tick_duration=0.01, gain=2)
        pid = model.module("PIDController", "PID", Kp=0.5)
        model.connect(sensor.OUTPUT, pid.INPUT, delay=1)
        net = model.build()
    """

    def __init__(self, name: str = "Main", /, **attrs: Any):
        node = _node("group", {"name": name, **attrs})
        super().__init__(node, None)
        self._classes: dict[str, type[Module]] = {}
        folder = os.path.dirname(node.file) if node.file and os.path.isfile(node.file) \
            else os.getcwd()
        self.filename = os.path.join(folder, f"{name}.ikg")

    @classmethod
    def _wrap(cls, node: Node, parent: "Group | None") -> "Group":
        group = cls.__new__(cls)
        Element.__init__(group, node, parent)
        group._classes = {}
        return group

    # --- files ---------------------------------------------------------------------------
    @classmethod
    def read(cls, filename: str) -> "Group":
        """The model of a file, to change in code and build or save."""
        from ..language.reader import read_file
        group = cls._wrap(read_file(filename, root_tag="group"), None)
        group.filename = os.path.abspath(filename)
        return group

    def save(self, filename: str) -> None:
        """Write the model as a .ikg file (the classes it uses must be found when it is
        loaded: a class given as a Python class needs its file beside the model)."""
        from ..language.writer import write_file
        write_file(self._top().node, filename)

    def to_xml(self) -> str:
        """The model as .ikg text."""
        from ..language.writer import to_text
        return to_text(self._top().node)

    # --- building the model ----------------------------------------------------------------
    def module(self, cls: str | type[Module], name: str | None = None, /,
               **parameters: Any) -> ModuleElement:
        """Add a module of class ``cls`` (a class name, or a Module subclass) named ``name``
        (default: the class name), with parameters as keywords."""
        if isinstance(cls, type):
            if not issubclass(cls, Module):
                raise TypeError(f"{cls.__name__} is not a subclass of ikaros.Module")
            self._top()._classes[cls.__name__] = cls
            class_name = cls.__name__
        else:
            class_name = cls
        node = _node("module", {"class": class_name, "name": name or class_name,
                                **parameters})
        self.node.children.append(node)
        return ModuleElement(node, self)

    def group(self, name: str, /, **attrs: Any) -> "Group":
        """Add a group inside this one."""
        node = _node("group", {"name": name, **attrs})
        self.node.children.append(node)
        return Group._wrap(node, self)

    def input(self, name: str, target: Port | str | None = None, **attrs: Any) -> Port:
        """Declare an input of this group; ``target`` is where it goes inside (optional:
        connections from the input may be made instead)."""
        self._port_decl("input", name, "target", target, attrs)
        return Port(self, name)

    def output(self, name: str, source: Port | str | None = None, **attrs: Any) -> Port:
        """Declare an output of this group; ``source`` is what inside it shows."""
        self._port_decl("output", name, "source", source, attrs)
        return Port(self, name)

    def _port_decl(self, tag, name, key, end, attrs) -> None:
        end = end.address(self) if isinstance(end, Port) else end
        self.node.children.append(_node(tag, {"name": name, key: end, **attrs}))

    def parameter(self, name: str, default: Any = None, **attrs: Any) -> Element:
        """Declare a group parameter (``target`` renames a parameter of a module inside)."""
        node = _node("parameter", {"name": name, "default": default, **attrs})
        self.node.children.append(node)
        return Element(node, self)

    def connect(self, source: Port | str, target: Port | str, delay=None, *,
                source_offset: int | None = None, target_offset: int | None = None,
                size: int | None = None, **attrs: Any) -> Connection:
        """Connect ``source`` to ``target``. ``delay``: a number of ticks, a ``range``
        (``range(1, 4)``: delays 1, 2, 3), a list ``[0, 2]``, or the language's text
        (``"1:3"``: 1, 2, 3 in an Ikaros 2 file, 1, 2 in an Ikaros 3 file).
        ``source_offset``, ``target_offset`` and ``size`` place a part of the source."""
        ends = {"source": source.address(self) if isinstance(source, Port) else source,
                "target": target.address(self) if isinstance(target, Port) else target}
        node = _node("connection", {**ends, "delay": _delay_text(delay),
                                    "sourceoffset": source_offset,
                                    "targetoffset": target_offset, "size": size, **attrs})
        self.node.children.append(node)
        return Connection(node, self)

    def view(self, name: str | None = None, **attrs: Any) -> View:
        """Add a view (a page of widgets in the web UI)."""
        node = _node("view", {"name": name, **attrs})
        self.node.children.append(node)
        return View(node, self)

    def widget(self, **attrs: Any) -> Element:
        """Add a widget directly in the group, as Ikaros 3 writes it (``<widget kind="plot"
        ...>``); ports given as attributes are named as this group sees them."""
        attrs = {k: (v.address(self) if isinstance(v, Port) else v) for k, v in attrs.items()}
        node = _node("widget", attrs)
        self.node.children.append(node)
        return Element(node, self)

    # --- finding and changing ----------------------------------------------------------------
    def __getitem__(self, name: str) -> "ModuleElement | Group":
        """A module or group inside by its name, or by a dotted path (``"Arm.PID"``)."""
        element: Group = self
        for part in name.split("."):
            found = element._child(part) if isinstance(element, Group) else None
            if found is None:
                raise KeyError(f'no module or group "{name}" in group "{self.name}"')
            element = found
        return element

    def _child(self, name: str):
        for node in self.node.elements():
            if node.tag in ("module", "group") and node.attrs.get("name") == name:
                return Group._wrap(node, self) if node.tag == "group" \
                    else ModuleElement(node, self)
        return None

    def __contains__(self, name: str) -> bool:
        try:
            self[name]
        except KeyError:
            return False
        return True

    @property
    def modules(self) -> list[ModuleElement]:
        return [ModuleElement(n, self) for n in self.node.elements("module")]

    @property
    def groups(self) -> list["Group"]:
        return [Group._wrap(n, self) for n in self.node.elements("group")]

    @property
    def connections(self) -> list[Connection]:
        return [Connection(n, self) for n in self.node.elements("connection")]

    @property
    def views(self) -> list[View]:
        return [View(n, self) for n in self.node.elements("view")]

    def walk(self) -> Iterator[Element]:
        """Every module and group inside, groups before their contents."""
        for node in self.node.elements():
            if node.tag == "group":
                group = Group._wrap(node, self)
                yield group
                yield from group.walk()
            elif node.tag == "module":
                yield ModuleElement(node, self)

    def remove(self, element: "Element | str") -> None:
        """Remove a module, group, connection or view; removing a module or group also
        removes the connections of this group to and from it."""
        if isinstance(element, str):
            element = self[element]
        if not _detach(self.node, element.node):
            raise KeyError(f"{element} is not in group \"{self.name}\"")
        if element.node.tag in ("module", "group"):
            prefix = (element.name or "") + "."
            for node in list(self.node.elements("connection")):
                ends = (node.attrs.get("source", ""), node.attrs.get("target", ""))
                if any(end.startswith(prefix) for end in ends):
                    _detach(self.node, node)

    def disconnect(self, source: Port | str, target: Port | str) -> int:
        """Remove the connections from ``source`` to ``target``; returns how many."""
        ends = tuple(e.address(self) if isinstance(e, Port) else e for e in (source, target))
        found = [c for c in self.node.elements("connection")
                 if (c.attrs.get("source"), c.attrs.get("target")) == ends]
        for node in found:
            _detach(self.node, node)
        return len(found)

    # --- running -------------------------------------------------------------------------
    def _top(self) -> "Group":
        group: Element = self
        while group.parent is not None:
            group = group.parent
        return cast("Group", group)

    def build(self, *, strict: bool = False, lenient: bool = False, quiet: bool = False,
              max_memory: int | str | None = None, **overrides: Any):
        """Build the network, as ``ikaros.load`` builds a file (same checks, same errors;
        an error names the line of the code that made the element)."""
        tree, classes = self.model_tree()
        return build_tree(tree, self._top().filename, strict=strict, lenient=lenient,
                          quiet=quiet, max_memory=max_memory, classes=classes, **overrides)

    def model_tree(self) -> tuple[Node, dict[str, type[Module]]]:
        """A copy of the model tree, and the Module subclasses given in code by name (what
        ``Network.apply`` builds)."""
        top = self._top()
        return top.node.copy(), dict(top._classes)

    def _repr_html_(self) -> str:
        return model_html(self)


def _detach(parent: Node, node: Node) -> bool:
    for i, child in enumerate(parent.children):
        if child is node:
            del parent.children[i]
            return True
    return False
