"""The errors the public API raises."""
from __future__ import annotations

MAX_REASON = 600    # characters of a reason shown (a hostile value may be megabytes long)


class ModelError(Exception):
    """A model cannot be read or built. The message names the file, the line and the element.

    ``filename`` and ``line`` say where (either may be None when no file is involved).
    """

    def __init__(self, message: str, filename: str | None = None, line: int | None = None,
                 element: str | None = None):
        if len(message) > MAX_REASON:
            message = f"{message[:MAX_REASON]}... ({len(message) - MAX_REASON} more characters)"
        self.reason = message
        self.filename = filename
        self.line = line
        self.element = element
        super().__init__(self._format())

    def _format(self) -> str:
        where = ""
        if self.filename:
            where = f"{self.filename}"
            if self.line:
                where += f":{self.line}"
            where += ": "
        elif self.line:
            where = f"line {self.line}: "
        what = f"{self.element}: " if self.element else ""
        return f"{where}{what}{self.reason}"


class RunError(Exception):
    """A run stopped because of a module's fatal error or exception. ``printed``: the
    network's log has printed the message already (the command line does not repeat it)."""

    def __init__(self, message: str, printed: bool = False):
        super().__init__(message)
        self.printed = printed
