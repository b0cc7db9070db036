"""The model tree: XML elements with their attributes, children, file and line."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterator

from ..errors import ModelError

COMMENT = "#comment"
INCLUDE = "#include"        # stands for <?include file="..."?>; its children are the spliced ones


@dataclass(eq=False, slots=True)
class Node:
    """One element of a model file. ``attrs`` keeps every attribute in file order."""
    tag: str
    attrs: dict[str, str] = field(default_factory=dict)
    children: list["Node"] = field(default_factory=list)
    file: str | None = None
    line: int | None = None
    text: str | None = None      # text content (descriptions), or a comment's text
    # a file's root only: the texts of the comments before and after the root element
    outside: tuple[list[str], list[str]] | None = None

    def elements(self, tag: str | None = None) -> Iterator["Node"]:
        """Child elements in document order, with included elements spliced in place."""
        for child in self.children:
            if child.tag == INCLUDE:
                yield from child.elements(tag)
            elif child.tag != COMMENT and (tag is None or child.tag == tag):
                yield child

    def get(self, key: str, default: str | None = None) -> str | None:
        return self.attrs.get(key, default)

    def label(self) -> str:
        """How error messages name this element: <module name="X">."""
        name = self.attrs.get("name")
        return f'<{self.tag} name="{name}">' if name is not None else f"<{self.tag}>"

    def error(self, message: str) -> ModelError:
        """A ModelError located at this element."""
        return ModelError(message, self.file, self.line, self.label())

    def copy(self) -> "Node":
        """A deep copy (the build works on copies, so the loaded tree stays as written)."""
        return Node(self.tag, dict(self.attrs), [c.copy() for c in self.children], self.file,
                    self.line, self.text, self._outside_copy())

    def _outside_copy(self):
        return None if self.outside is None else (list(self.outside[0]), list(self.outside[1]))
