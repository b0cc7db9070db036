"""Models built in code: the front-end objects (groups, modules, ports, connections, views)
over the model tree that files give. ``Group.build()`` builds them with the kernel's Builder,
as ``ikaros.load`` builds a file."""
from .elements import Connection, Element, Group, ModuleElement, Port, View

__all__ = ["Group", "ModuleElement", "Port", "Connection", "View", "Element"]
