"""The column-name convention and the delimiter parameter shared by InputCSV and OutputCSV.

A column is named NAME for a one-element value, NAME[i] for element i of a vector and
NAME[i][j] (or NAME[i,j]) for element (i, j) of a matrix, and so on for higher ranks.
"""
import itertools
import re

import numpy as np

from ._files import build_error

_COLUMN = re.compile(r"^(?P<name>[^\[\]]*?)\s*(?P<index>(?:\[[\d\s,]+\])*)$")
_INDEX = re.compile(r"\[([\d\s,]+)\]")


def port_name(text: str) -> str:
    """A column's base name as a port name: characters other than letters, digits, _ and -
    become _, and a name that does not start with a letter or _ gets a leading _."""
    name = re.sub(r"[^\w\-]", "_", text.strip())
    if not name or not (name[0].isalpha() or name[0] == "_"):
        name = "_" + name
    return name


def parse_column(text: str):
    """(base name, index tuple) of a header cell; the index is () for a plain name.
    Raises ValueError for a malformed name."""
    match = _COLUMN.match(text.strip())
    if not match or not match.group("name").strip():
        raise ValueError(f'bad column name "{text}"')
    index = []
    for group in _INDEX.findall(match.group("index")):
        parts = [p.strip() for p in group.split(",")]
        if not all(p.isdigit() for p in parts):
            raise ValueError(f'bad index in column name "{text}"')
        index.extend(int(p) for p in parts)
    return match.group("name").strip(), tuple(index)


def column_names(name: str, shape: tuple) -> list[str]:
    """The header cells of a value of this shape, in row-major order: NAME for a single
    element of rank 0 or 1, otherwise NAME[i] or NAME[i][j] ..."""
    if len(shape) <= 1 and int(np.prod(shape)) == 1:
        return [name]
    return [name + "".join(f"[{i}]" for i in idx)
            for idx in itertools.product(*(range(n) for n in shape))]


def csv_delimiter(module) -> str:
    """The module's ``delimiter`` parameter as one character ("tab" is a tab)."""
    text = module.delimiter
    result = "\t" if text.lower() in ("tab", "\\t", "\t") else text
    if len(result) != 1:
        raise build_error(module, f'delimiter "{text}" must be one character')
    return result
