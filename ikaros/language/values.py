"""Parsing attribute values: booleans, numbers, matrix literals, delays and selectors."""
from __future__ import annotations

import math
import re

import numpy as np

from ..limits import current as current_limits
from .expressions import ExpressionError, evaluate_arithmetic

TRUE_WORDS = {"true", "yes", "on", "1"}
FALSE_WORDS = {"false", "no", "off", "0"}


class ValueError_(ValueError):
    """A value that cannot be read; the caller adds where it was."""


def parse_bool(text: str) -> bool:
    """true/yes/on/1 and false/no/off/0 (any case); anything else is an error."""
    word = str(text).strip().lower()
    if word in TRUE_WORDS:
        return True
    if word in FALSE_WORDS:
        return False
    raise ValueError_(f'"{text}" is not a boolean (use true/yes/on/1 or false/no/off/0)')


def parse_number(text: str) -> float:
    """A number, or an arithmetic expression of numbers."""
    s = str(text).strip()
    try:
        return float(s)
    except ValueError:
        pass
    try:
        return evaluate_arithmetic(s)
    except ExpressionError as e:
        shown = s if len(s) <= 60 else f"{s[:40]}..."
        raise ValueError_(f'"{shown}" is not a number ({e})') from None


def parse_int(text: str) -> int:
    """An integer (a number with no fraction; arithmetic allowed)."""
    s = str(text).strip()
    if re.fullmatch(r"[+-]?\d+", s):
        return int(s)
    value = parse_number(s)
    if not math.isfinite(value):
        raise ValueError_(f'"{text}" is not a finite integer')
    if value != int(value):
        raise ValueError_(f'"{text}" is not an integer')
    return int(value)


def _strip_comments(text: str) -> str:
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def _element(token: str) -> float:
    try:
        number = float(token)
    except ValueError:
        pass
    else:
        if math.isinf(number) and "inf" not in token.lower():
            raise ValueError_(f'"{token}" is outside the range of a number')
        return number
    try:
        return evaluate_arithmetic(token)
    except ExpressionError:
        raise ValueError_(f'"{token}" is not a number') from None


def _elements(token: str) -> list[float]:
    """One element, or several when a comma-separated item holds numbers separated by
    white space (``1, 2 3``: commas and white space mixed in one row)."""
    parts = token.split()
    if len(parts) > 1:
        try:
            return [float(p) for p in parts]
        except ValueError:
            pass
    return [_element(token)]


@np.errstate(over="ignore")     # a number too big for float32 is inf, refused later
def parse_matrix(text: str) -> np.ndarray:
    """A matrix literal as a float32 array.

    Elements are separated by commas or white space, rows by ``;`` (a trailing ``;`` is
    ignored), ragged rows are padded with 0, ``#`` starts a comment, and nested brackets
    (``[[1,2],[3,4]]``) give any rank. One row gives a 1-D array.
    """
    s = _strip_comments(str(text)).strip()
    if s.startswith("["):
        return _parse_nested(s)
    if not s:
        return np.zeros((0,), dtype=np.float32)
    rows = [r for r in s.split(";")]
    if rows and not rows[-1].strip():
        rows.pop()
    split = (lambda r: [t for t in (x.strip() for x in r.split(","))]) if "," in s else \
        (lambda r: r.split())
    parsed = []
    for r in rows:
        tokens = split(r)
        if tokens == [""]:
            tokens = []
        if any(t == "" for t in tokens):
            raise ValueError_(f'"{text}" has an empty element')
        row = []
        for t in tokens:
            row.extend(_elements(t))
        parsed.append(row)
    if len(parsed) == 1 and ";" not in s:
        return _refuse_overflow(np.array(parsed[0], dtype=np.float32), parsed)
    width = max((len(r) for r in parsed), default=0)
    out = np.zeros((len(parsed), width), dtype=np.float32)
    for i, r in enumerate(parsed):
        out[i, :len(r)] = r
    return _refuse_overflow(out, parsed)


def _refuse_overflow(out: np.ndarray, parsed: list[list[float]]) -> np.ndarray:
    """Refuse a finite number too large for float32 (written nan and inf stay as they are,
    for the classes that accept them)."""
    if np.isinf(out).any():
        for number in (x for row in parsed for x in row):
            if math.isfinite(number) and math.isinf(np.float32(number)):
                raise ValueError_(f"{number:g} is outside the float32 range")
    return out


MAX_RANK = 32      # brackets nested in a matrix literal (NumPy allows 64 dimensions)


def _parse_nested(s: str) -> np.ndarray:
    tokens = re.findall(r"\[|\]|,|[^\[\],\s]+", s)
    depth = 0
    for tok in tokens:                  # before the recursive parse
        depth += (tok == "[") - (tok == "]")
        if depth > MAX_RANK:
            raise ValueError_(f"brackets nest deeper than {MAX_RANK} levels")
    pos = 0

    def value():
        nonlocal pos
        if pos >= len(tokens):
            raise ValueError_(f'"{s}": unbalanced brackets')
        tok = tokens[pos]
        if tok != "[":
            pos += 1
            return _element(tok)
        pos += 1
        items = []
        while pos < len(tokens) and tokens[pos] != "]":
            items.append(value())
            if pos < len(tokens) and tokens[pos] == ",":
                pos += 1
        if pos >= len(tokens):
            raise ValueError_(f'"{s}": unbalanced brackets')
        pos += 1
        return items

    nested = value()
    if pos != len(tokens):
        raise ValueError_(f'"{s}": text after the closing bracket')
    try:
        return np.array(nested, dtype=np.float32)
    except ValueError:
        raise ValueError_(f'"{s}": rows of different lengths in a bracketed literal') from None


_BRACKET = re.compile(r"\[([^\[\]]*)\]")


def parse_delays(text: str, wrap_ranges: bool = False) -> list[int]:
    """A delay attribute as the list of delays in listed order.

    ``n``; ``a:b`` inclusive; comma lists (``1,3,5:7``); ``[a:b]`` and ``[a:b:s]`` half-open
    (Ikaros 3); ``[n]``. With ``wrap_ranges`` (an Ikaros 3 file), a range without brackets
    is read as Ikaros 3 reads it, in brackets: ``1:3`` is ``[1:3]``, half-open.
    """
    s = str(text).strip()
    if wrap_ranges and ":" in s and "," not in s and not s.startswith("["):
        s = f"[{s}]"
    if s.isdigit():
        return [_delay_int(s, text)]
    if s == "":
        raise ValueError_("delay must not be empty")
    if s.startswith("["):
        groups = _BRACKET.findall(s)
        if "".join(f"[{g}]" for g in groups) != s.replace(" ", ""):
            raise ValueError_(f'delay "{text}" is not of the form [a:b] or [a:b:step]')
        if len(groups) != 1:
            raise ValueError_(f'delay range "{text}" must be one-dimensional')
        parts = [p.strip() for p in groups[0].split(":")]
        if parts == [""]:
            raise ValueError_(f'delay range "{text}" must not be empty')
        nums = [_delay_int(p, text) for p in parts]
        if len(nums) == 1:
            return _check_nonnegative([nums[0]], text)
        if len(nums) > 3:
            raise ValueError_(f'delay range "{text}" has too many parts')
        a, b = nums[0], nums[1]
        step = nums[2] if len(nums) == 3 else 1
        if step <= 0:
            raise ValueError_(f'delay range "{text}" must have a positive increment')
        _check_nonnegative([a, b], text)
        if b <= a:
            raise ValueError_(f'delay range "{text}" must be an ascending, non-empty range')
        return _check_count(list(range(a, b, step)), text)
    delays: list[int] = []
    for part in s.split(","):
        part = part.strip()
        if not part:
            raise ValueError_(f'delay "{text}" has an empty item')
        if ":" in part:
            bounds = [p.strip() for p in part.split(":")]
            if len(bounds) != 2:
                raise ValueError_(f'delay range "{part}" must be a:b')
            a, b = (_delay_int(p, text) for p in bounds)
            _check_nonnegative([a, b], text)
            if b < a:
                raise ValueError_(f'delay range "{text}" must be an ascending, non-empty range')
            delays.extend(range(a, b + 1))
            _check_count(delays, text)
        else:
            delays.append(_check_nonnegative([_delay_int(part, text)], text)[0])
    return _check_count(delays, text)


def _delay_int(part: str, text: str) -> int:
    if not (part.isascii() and part.isdigit()) and not re.fullmatch(r"[+-]?\d+", part):
        raise ValueError_(f'delay "{text}" is not a whole number or range')
    value, limit = int(part), current_limits().max_delay
    if value > limit:
        raise ValueError_(f'delay "{text}" is longer than the limit of {limit} ticks')
    return value


def _check_count(delays: list[int], text: str) -> list[int]:
    limit = current_limits().max_delays
    if len(delays) > limit:
        raise ValueError_(f'delay "{text}" lists more than {limit} delays')
    return delays


def _check_nonnegative(values: list[int], text: str) -> list[int]:
    if any(v < 0 for v in values):
        raise ValueError_(f'delay range "{text}" must be non-negative')
    return values


# A selector dimension: ("all",) for [], ("index", i) for [i], ("range", a, b, step).
_SELECTOR_TAIL = re.compile(r"((?:\[[^\[\]]*\])+)$")


def split_selectors(address: str) -> tuple[str, list[tuple] | None]:
    """Split ``A.OUTPUT[0:2][1]`` into the path and its selector dimensions (None if none)."""
    if not address.endswith("]"):
        return address, None
    m = _SELECTOR_TAIL.search(address)
    if not m:
        return address, None
    path = address[:m.start()].strip()
    dims = []
    for body in _BRACKET.findall(m.group(1)):
        body = body.strip()
        if body == "":
            dims.append(("all",))
            continue
        parts = [p.strip() for p in body.split(":")]
        if len(parts) == 1:
            dims.append(("index", _selector_int(parts[0], address)))
            continue
        if len(parts) > 3:
            raise ValueError_(f'selector "[{body}]" in "{address}" has too many parts')
        if parts[0] == "" and parts[1] == "" and len(parts) == 2:
            dims.append(("range", 0, 0, 1))       # [:] is explicitly empty
            continue
        a = _selector_int(parts[0], address)
        b = _selector_int(parts[1], address)
        step = _selector_int(parts[2], address) if len(parts) == 3 else 1
        if step == 0:
            raise ValueError_(f'selector "[{body}]" in "{address}" must not have a zero '
                              f'increment')
        if a < 0 or b < 0 or b < a:
            raise ValueError_(f'selector "[{body}]" in "{address}" must have non-negative, '
                              f'ordered bounds')
        dims.append(("range", a, b, step))
    return path, dims


def _selector_int(part: str, address: str) -> int:
    if not re.fullmatch(r"[+-]?\d+", part):
        raise ValueError_(f'selector in "{address}" is not made of whole numbers')
    return int(part)


def selector_indices(dim: tuple, extent: int) -> list[int]:
    """The indices one selector dimension picks from an axis of the given extent."""
    kind = dim[0]
    if kind == "all":
        return list(range(extent))
    if kind == "index":
        return [dim[1]]
    _, a, b, step = dim
    if step > 0:
        return list(range(a, b, step))
    return list(reversed(range(a, b, -step)))


def format_number(value: float) -> str:
    """A number as text: whole numbers without a fraction."""
    if float(value).is_integer():
        return str(int(value))
    return repr(float(value))


def value_text(value) -> str:
    """A Python value written as attribute text: numbers, booleans, arrays as literals."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, float, np.integer, np.floating)):
        return format_number(float(value))
    if hasattr(value, "tolist"):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        if value and isinstance(value[0], (list, tuple)):
            if any(isinstance(v, (list, tuple)) for row in value for v in row):
                return str(value).replace(" ", "")
            return "; ".join(", ".join(value_text(v) for v in row) for row in value)
        return ", ".join(value_text(v) for v in value)
    return str(value)
