"""Reading .ikg and .ikc files into model trees, with <?include file="..."?> spliced in."""
from __future__ import annotations

import os
import re

from lxml import etree

from ..errors import ModelError
from .node import COMMENT, INCLUDE, Node

MAX_INCLUDE_DEPTH = 32
_WRAPPER = "ikaros-file"
_DECLARATION = re.compile(r"^\s*<\?xml[^>]*\?>")
_DOCTYPE = re.compile(r"<!DOCTYPE[^>\[]*(\[[^\]]*\])?\s*>", re.S)


def _parser() -> etree.XMLParser:
    # No entity expansion beyond XML's own, no DTDs, no network: safe on untrusted files.
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           remove_blank_text=False, huge_tree=False)


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


def _parse_elements(path: str, text: str | None = None) -> list:
    """Parse a file as a list of top-level XML nodes (an included file need not have one root).

    Line numbers are those of the file: the wrapper element is put on its first line.
    """
    if text is None:
        try:
            with open(path, "rb") as f:
                raw = f.read()
        except OSError as e:
            raise ModelError(f"cannot read file: {e.strerror}", path) from None
        try:
            text = raw.decode("utf-8-sig")
        except UnicodeDecodeError as e:
            raise ModelError(f"file is not UTF-8 text ({e.reason} at byte {e.start})",
                             path) from None
    if "#" in text:
        text = _ATTRIBUTE_WITH_COMMENT.sub(_keep_newlines, text)
    text = _DECLARATION.sub(_keep_lines, text, count=1)
    if "<!DOCTYPE" in text:
        text = _DOCTYPE.sub(_keep_lines, text, count=1)
    wrapped = f"<{_WRAPPER}>{text}</{_WRAPPER}>"
    try:
        root = etree.fromstring(wrapped.encode("utf-8"), _parser())
    except etree.XMLSyntaxError as e:
        line = e.lineno or None
        msg = re.sub(r",? line \d+, column \d+$", "", e.msg or str(e))
        col = f" (column {e.position[1]})" if e.position and line != 1 else ""
        raise ModelError(f"malformed XML: {msg}{col}".replace(_WRAPPER, "file end"), path,
                         line) from None
    return list(root)


def _to_node(item, path: str, stack: tuple[str, ...]) -> Node | None:
    tag = item.tag
    if type(tag) is not str:          # a comment, a processing instruction or an entity
        if isinstance(item, etree._Comment):
            return Node(COMMENT, file=path, line=item.sourceline, text=item.text)
        if isinstance(item, etree._ProcessingInstruction) and item.target == "include":
            return _include(item, path, stack)
        return None
    text = item.text
    if text is not None:
        text = text.strip() or None
    children = []
    for child in item:
        converted = _to_node(child, path, stack)
        if converted is not None:
            children.append(converted)
    return Node(tag, dict(item.attrib), children, path, item.sourceline, text)


def _include(item, path: str, stack: tuple[str, ...]) -> Node:
    file = item.get("file")
    node = Node(INCLUDE, {"file": file or ""}, [], path, item.sourceline)
    if not file:
        raise ModelError('<?include?> needs a file="..." attribute', path, item.sourceline)
    target = os.path.normpath(os.path.join(os.path.dirname(path), file))
    if target in stack:
        raise ModelError(f'<?include file="{file}"?> includes itself', path, item.sourceline)
    if len(stack) >= MAX_INCLUDE_DEPTH:
        raise ModelError(f"includes nest deeper than {MAX_INCLUDE_DEPTH} levels", path,
                         item.sourceline)
    if not os.path.isfile(target):
        raise ModelError(f'included file "{file}" not found', path, item.sourceline)
    for child in _parse_elements(target):
        converted = _to_node(child, target, stack + (target,))
        if converted is not None:
            node.children.append(converted)
    return node


def read_file(path: str, text: str | None = None, root_tag: str | None = None) -> Node:
    """Read one model or class file into a Node tree.

    ``text`` parses that text as if it were the file at ``path``. ``root_tag`` checks the
    kind of the root element (``group`` or ``class``).
    """
    path = os.path.abspath(path)
    items = [n for n in (_to_node(i, path, (path,)) for i in _parse_elements(path, text))
             if n is not None]
    roots = [n for n in items if n.tag not in (COMMENT, INCLUDE)]
    if len(roots) != 1 or any(n.tag == INCLUDE for n in items):
        raise ModelError(f"a file must have exactly one root element, found {len(roots)}",
                         path, roots[1].line if len(roots) > 1 else None)
    root = roots[0]
    if root_tag and root.tag != root_tag:
        raise ModelError(f"the root element is <{root.tag}> but must be <{root_tag}>", path,
                         root.line)
    return root
