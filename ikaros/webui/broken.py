"""A model that fails to build, opened in the editor instead of ending the command.

``ikaros broken.ikg`` (with the web UI) reads the file's tree, finds the element at fault
in it (its id and path in the tree as JSON) by the error's file and line, or else by
building the tree once more the way the editor's Apply does, and serves an empty network of
the same name in its place. (An error with a line is never rebuilt: a module's ``init``
that failed, or one before it, must not run twice.) The web UI
then opens the editor on the file's tree with the error shown on that element; an Apply
that builds replaces the empty network. Batch mode (``-b``) still exits with the error.
"""
from __future__ import annotations

import os

from ..errors import ModelError
from ..language.node import Node
from ..language.reader import read_file
from . import editing


def open_broken(filename: str, overrides: dict, error: ModelError,
                max_memory: int | str | None = None):
    """(a stand-in network, the failure as served by ``/api/model``) for a model file whose
    build raised ``error``; re-raises ``error`` when the file can not be read as a tree
    (there is nothing to edit)."""
    from ..kernel.builder import Builder
    from ..language.diagnostics import Diagnostics
    from ..limits import Limits
    load_options = {"limits": Limits().with_memory(max_memory)}
    try:
        model = read_file(filename, root_tag="group")
    except ModelError:
        raise error from None
    folder = os.path.dirname(os.path.abspath(filename))
    tree = editing.tree_json(model, folder)
    failure = {"error": str(error), "node": None, "path": None}
    found = _node_at(tree, error, folder)
    if found is not None:
        failure.update(node=found[0], path=found[1])
    else:
        try:
            Builder(filename, overrides, model=editing.tree_from_json(tree, filename),
                    diagnostics=Diagnostics(quiet=True), **load_options).build().close()
        except ModelError as located:            # the same error, now with its element
            failure = editing.error_json(located)
        except Exception:
            pass
    empty = Node("group", {"name": model.attrs.get("name") or "Main"},
                 file=os.path.abspath(filename), line=1)
    net = Builder(filename, overrides, model=empty, diagnostics=Diagnostics(quiet=True),
                  **load_options).build()
    return net, {"file": os.path.basename(filename), "tree": tree, **failure}


def _node_at(tree: dict, error: ModelError, folder: str):
    """(id, path) of the element of the tree on the error's file and line (the one whose
    tag the error names, if several), or None."""
    if not error.filename or not error.line:
        return None
    file = os.path.relpath(os.path.abspath(error.filename), folder).replace(os.sep, "/")
    tag = (error.element or "").lstrip("<").split(" ")[0].rstrip(">")
    found = []

    def walk(node: dict, path: list[int]):
        if node.get("file") == file and node.get("line") == error.line:
            found.append((node["tag"] != tag, node["id"], path))
        for i, child in enumerate(node.get("children", ())):
            walk(child, path + [i])
    walk(tree, [])
    return min(found)[1:] if found else None
