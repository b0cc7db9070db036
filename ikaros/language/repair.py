"""The XML leniency of the original Ikaros parsers, as a repair of the text before parsing.

Both original parsers accept attributes with no whitespace between them (``x="1"y="2"``) and
a bare ``&`` (one that does not start ``&amp;``, ``&lt;``, ``&gt;``, ``&quot;``, ``&apos;`` or
a character reference); Ikaros 2 keeps the first of a repeated attribute. A file the strict
XML parser rejects is repaired here and parsed again; each repair is a warning naming the
file and line. Nothing here expands entities or reads other files, and newlines are kept, so
line numbers do not move.
"""
from __future__ import annotations

import bisect
import re

from .diagnostics import warn

_UNPARSED = r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|<!DOCTYPE[^>]*>"
_BARE_AMPERSAND = re.compile(rf"({_UNPARSED})|&(?!(?:amp|lt|gt|quot|apos|#\d+|#x[0-9A-Fa-f]+);)",
                             re.S)
_TAG = re.compile(rf"({_UNPARSED})|<([A-Za-z_][\w.:\-]*)((?:[^<>\"']|\"[^\"<]*\"|'[^'<]*')*)>",
                  re.S)
_ATTRIBUTE = re.compile(r"""([^\s=/>"']+)\s*=\s*("[^"<]*"|'[^'<]*')""")


class _Lines:
    def __init__(self, text: str):
        self.starts = [m.end() for m in re.finditer("\n", text)]

    def at(self, offset: int) -> int:
        return bisect.bisect_right(self.starts, offset) + 1


def repair(text: str, path: str, first_line: int = 1) -> str:
    """The text with the original's leniencies made well-formed XML (with a warning for
    each). ``first_line`` is the file line of the text's first line."""
    lines = _Lines(text)

    def line(offset: int) -> int:
        return lines.at(offset) + first_line - 1

    def ampersand(m: re.Match) -> str:
        if m.group(1):
            return m.group(1)
        warn("a bare & is read as a literal & (write &amp;)", path, line(m.start()))
        return "&amp;"

    def tag(m: re.Match) -> str:
        if m.group(1):
            return m.group(1)
        name, body = m.group(2), m.group(3)
        start = m.start(3)
        out, pos, seen, notes = [], 0, {}, []
        for a in _ATTRIBUTE.finditer(body):
            gap = body[pos:a.start()]
            key, value = a.group(1), a.group(2)
            where = line(start + a.start())
            if key in seen:
                notes.append((f'attribute "{key}" repeated; the first value, {seen[key]}, is '
                              f'kept', where))
                out.append(gap + "\n" * a.group(0).count("\n"))
            else:
                seen[key] = value
                if pos and not gap:
                    notes.append((f'no space before attribute "{key}"', where))
                    gap = " "
                out.append(gap + a.group(0))
            pos = a.end()
        out.append(body[pos:])
        label = f"<{name} name={seen['name']}>" if "name" in seen else f"<{name}>"
        for message, where in notes:
            warn(message, path, where, label)
        return f"<{name}{''.join(out)}>"

    if "&" in text:
        text = _BARE_AMPERSAND.sub(ampersand, text)
    return _TAG.sub(tag, text)
