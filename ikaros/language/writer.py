"""Writing a model tree back to .ikg text, keeping every attribute, comment and include."""
from __future__ import annotations

import os
import stat
import tempfile

from lxml import etree

from .node import COMMENT, INCLUDE, Node


def _element(node: Node):
    if node.tag == COMMENT:
        return etree.Comment(node.text or "")
    if node.tag == INCLUDE:
        return etree.ProcessingInstruction("include", f'file="{node.attrs.get("file", "")}"')
    el = etree.Element(node.tag)
    for key, value in node.attrs.items():
        el.set(key, value)
    if node.text:
        el.text = node.text
    for child in node.children:      # an include is written as itself, not its contents
        el.append(_element(child))
    return el


def to_text(root: Node) -> str:
    """The tree as XML text with an XML declaration (and the comments around the root)."""
    el = _element(root)
    etree.indent(el, space="    ")
    before, after = root.outside or ([], [])
    parts = [etree.tostring(etree.Comment(t), encoding="unicode") for t in before]
    parts.append(etree.tostring(el, encoding="unicode"))
    parts += [etree.tostring(etree.Comment(t), encoding="unicode") for t in after]
    return '<?xml version="1.0"?>\n' + "\n".join(parts) + "\n"


def _mode_for(filename: str) -> int:
    """The permission bits of the file that will be replaced, else 0666 less the umask."""
    try:
        return stat.S_IMODE(os.stat(filename).st_mode)
    except OSError:
        return 0o666 & ~_umask()


def _umask() -> int:
    try:                     # read without setting it (os.umask would, for all threads)
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    umask = os.umask(0o022)
    os.umask(umask)
    return umask


def write_file(root: Node, filename: str) -> None:
    """Write the tree to a file (written whole, then renamed, so a failure loses nothing).
    The file keeps the permissions of the one it replaces; a new file gets those the umask
    gives."""
    text = to_text(root)
    folder = os.path.dirname(os.path.abspath(filename))
    fd, tmp = tempfile.mkstemp(dir=folder, suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(tmp, _mode_for(filename))
        os.replace(tmp, filename)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
