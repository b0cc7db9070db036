"""Classes given in code: a Module subclass used directly in a builder is found by its name
before the model's folders, installed packages and the standard library."""
from __future__ import annotations

from .classes import ClassEntry, ClassRegistry
from ..module import Module


class CodeClassRegistry(ClassRegistry):
    """A class registry that also knows the Module subclasses given in code."""

    def __init__(self, folders: list[str], classes: dict[str, type[Module]]):
        super().__init__(folders)
        self._code = {name: ClassEntry(name, loaded=cls) for name, cls in classes.items()}

    def _find(self, name, extra_folders, skip_files):
        return self._code.get(name) or super()._find(name, extra_folders, skip_files)
