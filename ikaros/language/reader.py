"""Reading .ikg and .ikc files into model trees, with <?include file="..."?> spliced in."""
from __future__ import annotations

import os
import re
from xml.parsers import expat

from .. import access
from ..errors import ModelError
from ..limits import current as current_limits, format_bytes
from .node import COMMENT, INCLUDE, Node
from .repair import repair

MAX_INCLUDE_DEPTH = 32
_WRAPPER = "ikaros-file"
_DECLARATION = re.compile(r"^\s*<\?xml[^>]*\?>")
_DOCTYPE = re.compile(r"<!DOCTYPE[^>\[]*(\[[^\]]*\])?\s*>", re.S)
_PSEUDO_ATTRIBUTE = re.compile(r"""([\w.-]+)\s*=\s*(["'])(.*?)\2""", re.S)

# XML turns newlines in attribute values into spaces; a multi-line matrix literal with
# '#' comments needs them. Such values get character references (the newline stays too, so
# line numbers do not move, and becomes a harmless space).
_ATTRIBUTE_WITH_COMMENT = re.compile(r"""(=\s*)(["'])([^"'<>]*#[^"'<>]*)\2""")


def _keep_newlines(match: re.Match) -> str:
    if "\n" not in match.group(3):
        return match.group(0)
    value = match.group(3).replace("\n", "&#10;\n")
    return f"{match.group(1)}{match.group(2)}{value}{match.group(2)}"


def _keep_lines(match: re.Match) -> str:
    return "\n" * match.group(0).count("\n")


def _file_text(path: str) -> str:
    limit = current_limits().max_file_size
    try:
        with open(path, "rb") as f:
            raw = f.read(limit + 1)
    except OSError as e:
        raise ModelError(f"cannot read file: {e.strerror}", path) from None
    if len(raw) > limit:
        raise ModelError(f"the file is larger than the limit of {format_bytes(limit)}", path)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise ModelError(f"file is not UTF-8 text ({e.reason} at byte {e.start})",
                         path) from None


class _TreeBuilder:
    """Expat handlers that build Nodes (with their lines) as the file is parsed.

    Expat is used rather than lxml here because it calls back with each element and its
    line, so no intermediate element tree is built and walked: reading is twice as fast.
    It expands no external entities, and the DOCTYPE is removed before parsing.
    """

    def __init__(self, parser, path: str, stack: tuple[str, ...]):
        self.parser, self.path, self.stack = parser, path, stack
        self.top: list[Node] = []          # the file's top-level items
        self.open: list[Node] = []         # elements not yet closed, the wrapper excluded
        self.text: list[str] | None = None  # text of the innermost element before a child
        self.in_wrapper = False
        self.max_depth = current_limits().max_element_depth

    def _add(self, node: Node) -> None:
        if self.open:
            if self.text:
                self._keep_text()
            self.open[-1].children.append(node)
        else:
            self.top.append(node)
        self.text = None

    def _keep_text(self) -> None:
        """The innermost element's text so far is its text (what comes after a child is not
        kept, as in Ikaros)."""
        if self.text:
            self.open[-1].text = "".join(self.text).strip() or None

    def start(self, tag: str, attrs: dict) -> None:
        if not self.in_wrapper:             # the first element is always the wrapper
            self.in_wrapper = True
            return
        node = Node(tag, attrs, [], self.path, self.parser.CurrentLineNumber)
        if len(self.open) >= self.max_depth:
            raise node.error(f"elements nest deeper than {self.max_depth} levels")
        self._add(node)
        self.open.append(node)
        self.text = []

    def end(self, tag: str) -> None:
        if not self.open:
            return                          # the wrapper
        if self.text:
            self._keep_text()
        self.open.pop()
        self.text = None

    def data(self, text: str) -> None:
        if self.text is not None:
            self.text.append(text)
        elif not self.open and text.strip():
            raise ModelError(f'text outside the elements: "{text.strip()[:40]}"', self.path,
                             self.parser.CurrentLineNumber)

    def comment(self, text: str) -> None:
        self._add(Node(COMMENT, file=self.path, line=self.parser.CurrentLineNumber, text=text))

    def instruction(self, target: str, data: str) -> None:
        if target == "include":
            attrs = {m.group(1): m.group(3) for m in _PSEUDO_ATTRIBUTE.finditer(data)}
            self._add(_include(attrs.get("file"), self.path, self.parser.CurrentLineNumber,
                               self.stack))


def read_items(path: str, text: str | None = None,
               stack: tuple[str, ...] | None = None) -> list[Node]:
    """Parse a file into its top-level items (an included file need not have one root),
    with included files spliced in. Line numbers are those of the file."""
    if text is None:
        text = _file_text(path)
    if "#" in text:
        text = _ATTRIBUTE_WITH_COMMENT.sub(_keep_newlines, text)
    text = _DECLARATION.sub(_keep_lines, text, count=1)
    if "<!DOCTYPE" in text:
        text = _DOCTYPE.sub(_keep_lines, text, count=1)
    try:
        return _parse(text, path, stack)
    except expat.ExpatError as e:
        error = e
    repaired = repair(text, path)      # the original parsers' leniency, with warnings
    if repaired != text:
        try:
            return _parse(repaired, path, stack)
        except expat.ExpatError as e:
            error = e
    message = expat.errors.messages[error.code]
    col = f" (column {error.offset + 1})" if error.lineno != 1 else ""
    raise ModelError(f"malformed XML: {message}{col}", path, error.lineno) from None


def _parse(text: str, path: str, stack: tuple[str, ...] | None) -> list[Node]:
    parser = expat.ParserCreate()
    builder = _TreeBuilder(parser, path, stack if stack is not None else (path,))
    parser.buffer_text = True
    parser.StartElementHandler = builder.start
    parser.EndElementHandler = builder.end
    parser.CharacterDataHandler = builder.data
    parser.CommentHandler = builder.comment
    parser.ProcessingInstructionHandler = builder.instruction
    parser.Parse(f"<{_WRAPPER}>{text}</{_WRAPPER}>", True)
    return builder.top


class IncludeError(ModelError):
    """An error found through an include, told once where it is (an include above it
    passes it on as it is, not wrapped again)."""


def _chain(stack: tuple[str, ...]) -> str:
    """" (through top.ikg > a.ikg > b.ikg)" when an include is nested, else ""."""
    if len(stack) < 2:
        return ""
    return f" (through {' > '.join(os.path.basename(p) for p in stack)})"


def _include(file: str | None, path: str, line: int, stack: tuple[str, ...]) -> Node:
    node = Node(INCLUDE, {"file": file or ""}, [], path, line)
    if not file:
        raise ModelError('<?include?> needs a file="..." attribute', path, line)
    confinement = access.current()
    if confinement is not None:
        try:
            confinement.check(file, os.path.dirname(path), "included file")
        except access.AccessRefused as e:
            raise ModelError(str(e), path, line) from None
    target = os.path.normpath(os.path.join(os.path.dirname(path), file))
    if target in stack:
        raise IncludeError(f'<?include file="{file}"?> includes itself{_chain(stack)}',
                           path, line)
    if len(stack) >= MAX_INCLUDE_DEPTH:
        raise IncludeError(f"includes nest deeper than {MAX_INCLUDE_DEPTH} levels"
                           f"{_chain(stack)}", path, line)
    if not os.path.isfile(target):
        raise IncludeError(f'included file "{file}" not found{_chain(stack)}', path, line)
    try:
        items = read_items(target, stack=stack + (target,))
    except IncludeError:
        raise                           # told where it is, once
    except ModelError as e:
        if e.filename != target:
            raise                       # the error of a file that one includes
        raise IncludeError(f'included file "{file}" is not model text{_chain(stack)}: {e}',
                           path, line) from None
    node.children.extend(items)
    return node


def read_file(path: str, text: str | None = None, root_tag: str | None = None) -> Node:
    """Read one model or class file into a Node tree.

    ``text`` parses that text as if it were the file at ``path``. ``root_tag`` checks the
    kind of the root element (``group`` or ``class``).
    """
    path = os.path.abspath(path)
    items = read_items(path, text)
    roots = [n for n in items if n.tag not in (COMMENT, INCLUDE)]
    if len(roots) != 1 or any(n.tag == INCLUDE for n in items):
        raise ModelError(f"a file must have exactly one root element, found {len(roots)}",
                         path, roots[1].line if len(roots) > 1 else None)
    root = roots[0]
    at = items.index(root)
    before = [n.text or "" for n in items[:at]]
    after = [n.text or "" for n in items[at + 1:]]
    if before or after:
        root.outside = (before, after)
    if root_tag and root.tag != root_tag:
        raise ModelError(f"the root element is <{root.tag}> but must be <{root_tag}>", path,
                         root.line)
    return root
