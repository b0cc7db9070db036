"""The instance tree: groups and modules as built from the model file, with their paths."""
from __future__ import annotations

from typing import Iterator

from ..language.node import Node


class Component:
    """A group or a module in the built model. ``attrs`` are the element's attributes."""

    def __init__(self, name: str, node: Node, parent: "Group | None",
                 attrs: dict | None = None):
        self.name = name
        self.node = node
        self.parent = parent
        self.attrs = node.attrs if attrs is None else attrs
        # the dotted path from the top group, without the top group's name
        if parent is None:
            self.path = ""
        else:
            self.path = f"{parent.path}.{name}" if parent.path else name

    def top(self) -> "Group":
        c = self
        while c.parent is not None:
            c = c.parent
        return c

    def chain(self) -> Iterator["Component"]:
        """This component, then its enclosing groups outward."""
        c = self
        while c is not None:
            yield c
            c = c.parent


class Group(Component):
    #: the top group's: the top-level settings' defaults, where a variable's lookup ends
    defaults: dict[str, str] = {}

    def __init__(self, name: str, node: Node, parent: "Group | None",
                 attrs: dict | None = None):
        super().__init__(name, node, parent, attrs)
        self.children: dict[str, Component] = {}
        self.connections: list[Node] = []
        self.inputs: list[Node] = []
        self.outputs: list[Node] = []
        self.renamings: list[Node] = []
        self.views: list[Node] = []

    def walk(self) -> Iterator[Component]:
        """Every component below this group, in document order (groups before their
        contents)."""
        for child in self.children.values():
            yield child
            if isinstance(child, Group):
                yield from child.walk()

    def modules(self) -> Iterator["ModuleInstance"]:
        return (c for c in self.walk() if isinstance(c, ModuleInstance))


class ModuleInstance(Component):
    def __init__(self, name: str, node: Node, parent: Group, entry, order: int):
        super().__init__(name, node, parent)
        self.entry = entry
        self.order = order                 # declaration order, for schedule ties
        self.module = None                 # the Python Module object
        self.values: dict[str, object] = {}       # resolved parameter values
        self.has_value: dict[str, bool] = {}      # whether a parameter had a value at all
        self.period = 1                    # ticks only when tick % period == phase
        self.phase = 0
        self.asynchronous = False          # tick runs in the background
        self.module_start = "at_tick"      # Ikaros 3 start gating (kernel/gating.py)
        self.start_tick = 0
        self.first_tick: int | None = 0    # the first tick it runs (None: never)
        self.shape_attribute = None        # Ikaros 3 size="..."/shape="..." on the element

    @property
    def every_tick(self) -> bool:
        """Whether it runs on every tick from the first (no period, phase or start)."""
        return self.period == 1 and self.first_tick == 0


class Scope:
    """A lookup scope for variables that is not a component (a connection element)."""

    def __init__(self, node: Node, parent: Group):
        self.node = node
        self.attrs = node.attrs
        self.parent = parent

    def chain(self):
        yield self
        yield from self.parent.chain()

    def top(self):
        return self.parent.top()


def group_of(scope) -> Group:
    """The group paths are relative to, for a scope."""
    if isinstance(scope, Group):
        return scope
    return scope.parent


def find_component(start: Group, path: str) -> Component | None:
    """Resolve a dotted component path from a group.

    A leading ``.`` starts at the top group (whose name may then be given or left out). A
    segment names a child, or else an enclosing group (nearest first), which climbs to it.
    """
    if path.startswith("."):
        current: Component = start.top()
        segments = path[1:].split(".")
        if segments and segments[0] == current.name and segments[0] not in current.children:
            segments = segments[1:]
    else:
        current = start
        segments = path.split(".")
    for seg in segments:
        if seg == "":
            return None
        if isinstance(current, Group) and seg in current.children:
            current = current.children[seg]
            continue
        ancestor = next((c for c in current.chain() if c.name == seg), None)
        if ancestor is None:
            return None
        current = ancestor
    return current
