"""Helpers shared by the file modules: paths, numbered file names, build errors."""
import os
import re

from ikaros.module import ModelError

_COUNTER = re.compile(r"%(0?\d*)d|#+")


def model_folder(module) -> str:
    """The folder of the model file that holds the module (the working folder if none)."""
    model_file = getattr(module.element, "file", None)
    return os.path.dirname(os.path.abspath(model_file)) if model_file else os.getcwd()


def resolve(module, filename: str, write: bool = False) -> str:
    """A file name relative to the model file's folder, as an absolute path. With
    ``write``, relative to the user-data folder when there is one (``ikaros -u DIR``), and
    the file's folder is made if it is missing (so ``output/x.csv`` works)."""
    folder = (write and module.user_data) or model_folder(module)
    path = filename if os.path.isabs(filename) else os.path.join(folder, filename)
    if write:
        os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    return path


def numbered(pattern: str, number: int) -> str:
    """The file name with ``%d`` (or ``%03d`` and so on, Ikaros 2) or a run of ``#``
    (Ikaros 3: ``###`` is three digits, zero-padded) replaced by ``number``."""
    def one(m):
        text = m.group(0)
        if text.startswith("#"):
            return f"{number:0{len(text)}d}"
        return ("%" + m.group(1) + "d") % number
    return _COUNTER.sub(one, pattern)


def has_counter(pattern: str) -> bool:
    return _COUNTER.search(pattern) is not None


def counter_capacity(pattern: str) -> int | None:
    """How many file numbers a run of ``#`` can hold (``##``: 100), or None for no limit."""
    runs = [len(m.group(0)) for m in _COUNTER.finditer(pattern) if m.group(0)[0] == "#"]
    return 10 ** min(runs) if runs else None


def build_error(module, message: str) -> ModelError:
    """A ModelError located at the module's element."""
    element = module.element
    if element is not None and hasattr(element, "error"):
        return element.error(message)
    return ModelError(message)
