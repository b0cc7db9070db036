"""The network editor's server side: the model tree as JSON and back, and the folder rule.

The tree as JSON (docs/webui-protocol.md, "The editor")::

    {"id": 3, "tag": "module", "attrs": {...in file order...}, "text": null,
     "children": [...], "file": "demo.ikg", "line": 12}

``tree_json`` numbers the nodes of the running network's model tree in document order
(1, 2, ...; included nodes too); ``file`` is relative to the model's folder.

Locating errors
---------------
``tree_from_json`` makes every node an ``EditorNode``: a ``Node`` that also carries ``ref``,
the JSON node's ``(id, path)`` (``id`` as sent, ``None`` for nodes the app created; ``path``
the child indices from the root). ``EditorNode.error`` -- the way the builder reports a
problem at an element -- puts that ``ref`` on the ``ModelError`` it makes
(``ModelError.editor_ref``), so ``locate(error)`` gives the id and path of the element at
fault exactly, however the tree was edited. (Synthetic line numbers are not used: a node's
``file`` must stay a real path, since ``external`` group files and class folders are found
relative to it.)

What the client sends is trusted only as data: ``file`` is never taken from it. Nodes
outside includes get the model's file; ``line`` is kept from the JSON as a hint for the
message (the line the element had in the file as loaded; ``None`` for new nodes). An
``<?include?>`` is read again from disk (its JSON children are the read-only display, and
saving writes the include, not its contents, so apply runs what a save would load); the
nodes read get their real file and line, and the ``ref`` of the JSON node with the same
file, line and tag under that include (the include's own ``ref`` when there is none).
An error that no ``EditorNode`` made (inside an ``external`` group file or a group class,
which the editor does not show) has no location: ``(None, None)``.

The folder rule
---------------
Files are saved, listed, opened and created only as plain ``*.ikg`` names (no folder part,
no ``..``, no leading dot) in one folder: the ``--models DIR`` given on the command line, or
else the folder of the model the server started with. Saving without a name writes the
model's file (after a save-as, the new one).
"""
from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass

from .. import access
from ..errors import ModelError
from ..language.node import COMMENT, INCLUDE, Node
from ..language.reader import MAX_INCLUDE_DEPTH, read_items

MAX_NODES = 100_000
MAX_DEPTH = 100
NODE_KEYS = ("id", "tag", "attrs", "text", "children", "file", "line", "outside")
_XML_NAME = re.compile(r"[A-Za-z_][\w.\-]*\Z", re.ASCII)
_BAD_CHARS = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")
_FILE_NAME = re.compile(r"[^\W][\w\-. ]*\.ikg\Z")
_MODEL_NAME = re.compile(r"[A-Za-z_][\w\-]*\Z")


class TreeError(ValueError):
    """The JSON is not a model tree (answered with 400)."""


class NameRefused(PermissionError):
    """A file name outside the folder rule (answered with 403)."""


@dataclass(eq=False)
class EditorNode(Node):
    """A node built from the editor's JSON: ``ref`` is ``(id, path)`` of that JSON node."""
    ref: tuple | None = None

    def error(self, message: str) -> ModelError:
        e = super().error(message)
        e.editor_ref = self.ref
        return e

    def copy(self) -> "EditorNode":
        return EditorNode(self.tag, dict(self.attrs), [c.copy() for c in self.children],
                          self.file, self.line, self.text, self._outside_copy(), self.ref)


def locate(error: ModelError) -> tuple[int | None, list[int] | None]:
    """(id, path) of the element at fault, or (None, None)."""
    ref = getattr(error, "editor_ref", None)
    if ref is None:
        return None, None
    return ref[0], list(ref[1])


def error_json(error: ModelError) -> dict:
    node, path = locate(error)
    return {"error": str(error), "node": node, "path": path}


# --- tree -> JSON -------------------------------------------------------------------------

def tree_json(root: Node, folder: str) -> dict:
    """The tree as JSON with ids in document order; files relative to ``folder``."""
    counter = [0]

    def rel(file):
        if not file:
            return None
        try:
            return os.path.relpath(file, folder).replace(os.sep, "/")
        except ValueError:                 # another drive
            return os.path.basename(file)

    def walk(node: Node) -> dict:
        counter[0] += 1
        return {"id": counter[0], "tag": node.tag, "attrs": dict(node.attrs),
                "text": node.text, "children": [walk(c) for c in node.children],
                "file": rel(node.file), "line": node.line}
    out = walk(root)
    if root.outside:
        out["outside"] = {"before": list(root.outside[0]), "after": list(root.outside[1])}
    return out


# --- JSON -> tree -------------------------------------------------------------------------

def _text(value, what: str) -> str:
    if _BAD_CHARS.search(value):
        raise TreeError(f"{what} holds a character XML does not allow")
    return value


def _whole(value) -> bool:
    """A JSON whole number (2 and 2.0 alike, as JSON Schema counts them)."""
    return (isinstance(value, int) and not isinstance(value, bool)) or \
        (isinstance(value, float) and value.is_integer())


def _check(data, path: tuple, depth: int, count: list) -> dict:
    """Validate one JSON node (not its children); returns the cleaned fields."""
    where = "the tree" if not path else "node at path " + "/".join(map(str, path))
    if not isinstance(data, dict):
        raise TreeError(f"{where} must be a JSON object")
    count[0] += 1
    if count[0] > MAX_NODES:
        raise TreeError(f"the tree has more than {MAX_NODES} nodes")
    if depth > MAX_DEPTH:
        raise TreeError(f"the tree is nested deeper than {MAX_DEPTH} levels")
    for key in data:
        if key not in NODE_KEYS:
            raise TreeError(f'{where}: unknown field "{key}" (expected: '
                            f'{", ".join(NODE_KEYS)})')
    tag = data.get("tag")
    if not isinstance(tag, str) or not (tag in (COMMENT, INCLUDE) or _XML_NAME.match(tag)):
        raise TreeError(f'{where}: "tag" must be an element name, "#comment" or "#include"')
    node_id = data.get("id")
    if node_id is not None and not (_whole(node_id) and node_id >= 0):
        raise TreeError(f'{where}: "id" must be a whole number >= 0 or absent')
    node_id = None if node_id is None else int(node_id)
    line = data.get("line")
    if line is not None and not (_whole(line) and line >= 1):
        raise TreeError(f'{where}: "line" must be a whole number >= 1 or absent')
    line = None if line is None else int(line)
    file = data.get("file")
    if file is not None and not isinstance(file, str):
        raise TreeError(f'{where}: "file" must be a string or absent')
    attrs = data.get("attrs", {})
    if attrs is None:
        attrs = {}
    if not isinstance(attrs, dict):
        raise TreeError(f'{where}: "attrs" must be an object of name: value')
    clean = {}
    for key, value in attrs.items():
        if not _XML_NAME.match(key):
            raise TreeError(f'{where}: "{key[:40]}" is not an attribute name')
        if isinstance(value, bool) or not isinstance(value, (str, int, float)):
            raise TreeError(f'{where}: attribute "{key}" must be a string')
        if isinstance(value, float):
            if not math.isfinite(value):
                raise TreeError(f'{where}: attribute "{key}" is not a finite number')
            value = repr(value) if value != int(value) else str(int(value))
        clean[key] = _text(str(value), f'{where}: attribute "{key}"')
    text = data.get("text")
    if text is not None:
        if not isinstance(text, str):
            raise TreeError(f'{where}: "text" must be a string or null')
        _text(text, f"{where}: the text")
    children = data.get("children", [])
    if children is None:
        children = []
    if not isinstance(children, list):
        raise TreeError(f'{where}: "children" must be a list')
    if tag == COMMENT:
        if clean or children:
            raise TreeError(f"{where}: a comment has only text")
        if text and ("--" in text or text.endswith("-")):
            raise TreeError(f'{where}: a comment must not contain "--" or end with "-"')
    if tag == INCLUDE:
        inc = clean.get("file", "")
        if set(clean) != {"file"} or not inc.strip(" \t\r\n") or '"' in inc or "?>" in inc:
            raise TreeError(f'{where}: an include needs just attrs.file, a file name '
                            f'without quotes')
    return {"tag": tag, "id": node_id, "line": line, "file": file, "attrs": clean,
            "text": text, "children": children, "outside": _outside(data, path, where)}


def _outside(data: dict, path: tuple, where: str):
    """The root's comments before and after it: {"before": [text], "after": [text]}."""
    value = data.get("outside")
    if value is None:
        return None
    if path:
        raise TreeError(f'{where}: only the root has "outside" comments')
    if not isinstance(value, dict) or set(value) - {"before", "after"}:
        raise TreeError(f'{where}: "outside" must be {{"before": [...], "after": [...]}}')
    lists = []
    for key in ("before", "after"):
        texts = value.get(key, [])
        if not isinstance(texts, list) or not all(isinstance(t, str) for t in texts):
            raise TreeError(f'{where}: "outside.{key}" must be a list of comment texts')
        for t in texts:
            _text(t, f"{where}: a comment")
            if "--" in t or t.endswith("-"):
                raise TreeError(f'{where}: a comment must not contain "--" or end with "-"')
        lists.append(list(texts))
    return tuple(lists)


def tree_from_json(data, filename: str, reread_includes: bool = True) -> EditorNode:
    """The model tree of the JSON ``data`` for the model file ``filename``.

    Raises TreeError when ``data`` is not a tree, and ModelError (located at the include)
    when an included file can not be read. With ``reread_includes`` false (saving), an
    include keeps no children: only the include itself is written."""
    filename = os.path.abspath(filename)
    folder = os.path.dirname(filename)
    count = [0]

    def convert(data, path: tuple, depth: int, shown: bool) -> EditorNode:
        # ``shown``: a node displayed under an include (kept only to locate errors)
        f = _check(data, path, depth, count)
        node = EditorNode(f["tag"], f["attrs"], [], filename, f["line"], f["text"],
                          f["outside"] if not path else None, (f["id"], path))
        node._sent_file = f["file"]
        inside = shown or f["tag"] == INCLUDE
        kids = [convert(c, path + (i,), depth + 1, inside)
                for i, c in enumerate(f["children"])]
        if f["tag"] != INCLUDE or shown:
            node.children = kids
        elif reread_includes:
            node.children = _read_include(node, filename, folder, kids, (filename,))
        return node

    root = convert(data, (), 0, False)
    if root.tag != "group":
        raise TreeError(f'the root must be a <group> element, not "{root.tag}"')
    return root


def _json_index(kids: list[EditorNode], folder: str, index: dict) -> dict:
    """{(file, line, tag): ref} of the JSON nodes under an include (their ``file`` and
    ``line`` as sent, kept on the side before the nodes get the real ones)."""
    for kid in kids:
        kid_file = getattr(kid, "_sent_file", None)
        if kid_file and kid.line:
            index.setdefault((os.path.normpath(os.path.join(folder, kid_file)), kid.line,
                              kid.tag), kid.ref)
        _json_index(kid.children, folder, index)
    return index


def _read_include(inc: EditorNode, containing: str, folder: str, kids: list,
                  stack: tuple) -> list[EditorNode]:
    file = inc.attrs["file"]
    confinement = access.current()
    if confinement is not None:
        try:
            confinement.check(file, os.path.dirname(containing), "included file")
        except access.AccessRefused as e:
            raise inc.error(str(e)) from None
    target = os.path.normpath(os.path.join(os.path.dirname(containing), file))
    if target in stack:
        raise inc.error(f'<?include file="{file}"?> includes itself')
    if len(stack) >= MAX_INCLUDE_DEPTH:
        raise inc.error(f"includes nest deeper than {MAX_INCLUDE_DEPTH} levels")
    if not os.path.isfile(target):
        raise inc.error(f'included file "{file}" not found')
    index = _json_index(kids, folder, {})
    try:
        items = read_items(target, stack=stack + (target,))
    except ModelError as e:
        if getattr(e, "editor_ref", None) is None:
            e.editor_ref = inc.ref
        raise
    return [_retag(n, index, inc.ref) for n in items]


def _retag(node: Node, index: dict, default: tuple) -> EditorNode:
    ref = index.get((os.path.normpath(node.file or ""), node.line, node.tag), default)
    return EditorNode(node.tag, dict(node.attrs), [_retag(c, index, ref) for c in
                                                    node.children],
                      node.file, node.line, node.text, ref=ref)


# --- files and the folder rule ------------------------------------------------------------

def file_in(folder: str, name) -> str:
    """The path of a plain ``*.ikg`` file name in ``folder``; NameRefused otherwise."""
    if not isinstance(name, str) or not 5 <= len(name) <= 255 or ".." in name \
            or not _FILE_NAME.match(name) or name != name.strip():
        raise NameRefused(f"{str(name)[:80]!r} is not a plain .ikg file name in the models "
                          f"folder (letters, digits, _ - . and spaces, ending in .ikg)")
    folder = os.path.abspath(folder)
    path = os.path.join(folder, name)
    if os.path.dirname(os.path.abspath(path)) != folder:
        raise NameRefused(f"{name!r} is outside the models folder")
    if os.path.lexists(path) and not os.path.isfile(path) and not os.path.islink(path):
        raise NameRefused(f"{name!r} is not a file")
    return path


def model_files(folder: str) -> list[str]:
    """The plain ``*.ikg`` files in ``folder``, sorted."""
    try:
        names = os.listdir(folder)
    except OSError:
        return []
    out = []
    for name in names:
        try:
            path = file_in(folder, name)
        except NameRefused:
            continue
        if os.path.isfile(path):
            out.append(name)
    return sorted(out, key=lambda n: (n.lower(), n))


def new_model(folder: str, name: str) -> tuple[Node, str]:
    """An empty model (one group named ``name``) and a file name in ``folder`` not yet
    taken: ``Name.ikg``, else ``Name-2.ikg``, ..."""
    if not isinstance(name, str) or not _MODEL_NAME.match(name) or len(name) > 100:
        raise TreeError(f'"name" must be a model name: letters, digits, _ and -, not '
                        f'starting with a digit (not {str(name)[:40]!r})')
    for k in range(1, 10000):
        file = os.path.join(folder, f"{name}.ikg" if k == 1 else f"{name}-{k}.ikg")
        if not os.path.lexists(file):
            break
    else:
        raise TreeError(f'too many models named "{name}"')
    return Node("group", {"name": name}, [], file, None, None), file
