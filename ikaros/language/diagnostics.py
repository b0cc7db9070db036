"""Load-time warnings: what the original Ikaros accepts but a clean file would not say.

A build runs inside ``collecting(Diagnostics(...))``; the reader, the class files and the
builder report through ``warn``. Each warning names the file, the line and the element. In
strict mode a warning is raised as a ModelError instead; lenient mode turns some errors
(connections to nothing) into warnings.
"""
from __future__ import annotations

import contextlib
import sys
from contextvars import ContextVar
from dataclasses import dataclass

from ..errors import ModelError


@dataclass(frozen=True)
class ModelWarning:
    """One load-time warning: where (file, line, element) and what; ``module`` is the path
    of the module that gave it (a module's warning in configure or init)."""
    message: str
    filename: str | None = None
    line: int | None = None
    element: str | None = None
    module: str | None = None

    def __str__(self) -> str:
        return f"{self._where()}warning: {self._what()}"

    def as_note(self) -> str:
        """The record as a note: ``file:line: note: message``."""
        return f"{self._where()}note: {self._what()}"

    def located(self) -> str:
        """The warning without the word "warning": ``file:line: <element>: message``."""
        return self._where() + self._what()

    def _where(self) -> str:
        if self.filename:
            return f"{self.filename}:{self.line}: " if self.line else f"{self.filename}: "
        return ""

    def _what(self) -> str:
        return f"{self.element}: {self.message}" if self.element else self.message


class Diagnostics:
    """Collects the warnings of one load. ``quiet`` prints nothing; ``strict`` raises each
    warning as a ModelError; ``lenient`` lets the loader drop what the original drops."""

    def __init__(self, strict: bool = False, lenient: bool = False, quiet: bool = False):
        self.strict, self.lenient, self.quiet = strict, lenient, quiet
        self.warnings: list[ModelWarning] = []
        self.notes: list[ModelWarning] = []      # information, never an error

    def fresh(self) -> "Diagnostics":
        """New, empty diagnostics with the same settings (for building the model again)."""
        return Diagnostics(self.strict, self.lenient, self.quiet)

    def warn(self, message: str, filename: str | None = None, line: int | None = None,
             element: str | None = None, module: str | None = None) -> ModelWarning | None:
        """Keep (and print) a warning; None when the same one was given before."""
        if self.strict:
            raise ModelError(f"{message} (an error with --strict)", filename, line, element)
        record = ModelWarning(message, filename, line, element, module)
        if record in self.warnings:
            return None
        self.warnings.append(record)
        if not self.quiet:
            print(record, file=sys.stderr, flush=True)
        return record

    def note(self, message: str, filename: str | None = None, line: int | None = None) -> None:
        """A line of information about the load (which dialect was chosen, and why): printed
        like a warning, but never an error, not even with --strict."""
        record = ModelWarning(message, filename, line)
        self.notes.append(record)
        if not self.quiet:
            print(record.as_note(), file=sys.stderr, flush=True)


_current: ContextVar[Diagnostics | None] = ContextVar("ikaros_diagnostics", default=None)


def current() -> Diagnostics:
    """The diagnostics of the load in progress (outside a load: print to stderr)."""
    return _current.get() or Diagnostics()


def warn(message: str, filename: str | None = None, line: int | None = None,
         element: str | None = None) -> None:
    current().warn(message, filename, line, element)


def warn_at(node, message: str) -> None:
    """A warning located at a model-tree element."""
    current().warn(message, node.file, node.line, node.label())


def lenient() -> bool:
    return current().lenient


@contextlib.contextmanager
def collecting(diagnostics: Diagnostics):
    token = _current.set(diagnostics)
    try:
        yield diagnostics
    finally:
        _current.reset(token)
