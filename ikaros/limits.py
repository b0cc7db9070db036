"""Limits that keep a mistaken or hostile model from exhausting memory, the stack or time.

Every build runs under one ``Limits`` (``ikaros.load(..., max_memory=...)``, ``ikaros
--max-memory``); the checks in the reader, the builder and the kernel read it with
``current()``. A model that passes a limit gets a ModelError naming the element.
"""
from __future__ import annotations

import contextlib
import contextvars
import os
import re
import threading
from dataclasses import dataclass, field, replace

BYTES_PER_ELEMENT = 4            # buffers are float32
# what building one module takes besides its buffers (its objects, ports, schedule entry),
# measured with the lightest class (Constant: about 6 KB a module from 2e4 to 1e5 modules)
BYTES_PER_MODULE = 6 << 10


def physical_memory() -> int:
    """The machine's memory in bytes (0 when it cannot be told)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (AttributeError, ValueError, OSError):
        return 0


def default_max_memory() -> int:
    """Half of the physical memory (4 GB when it cannot be told)."""
    return physical_memory() // 2 or 4 << 30


@dataclass(frozen=True)
class Limits:
    """The limits of one build. ``max_memory`` is in bytes."""
    max_memory: int = field(default_factory=default_max_memory)  # all buffers and rings
    max_file_size: int = 128 << 20    # bytes of one model, group or class file
    max_element_depth: int = 200      # nesting of elements in one file
    max_group_depth: int = 100        # nesting of groups, across files
    max_expression_depth: int = 100   # nesting of parentheses in an arithmetic expression
    max_expansion: int = 1_000_000    # characters a value may grow to by its variables
    max_lookups: int = 100_000        # variable lookups to resolve one value
    max_delay: int = 100_000          # ticks of one connection delay
    max_delays: int = 10_000          # delays listed in one connection

    def with_memory(self, max_memory: int | str | None) -> "Limits":
        """These limits with ``max_memory`` (bytes, or text like ``512M``, ``2G``)."""
        if max_memory is None:
            return self
        return replace(self, max_memory=parse_bytes(max_memory))


class LimitError(ValueError):
    """A limit was passed; the caller names the element."""


_current: contextvars.ContextVar[Limits | None] = contextvars.ContextVar("ikaros_limits",
                                                                         default=None)
_DEFAULT: list[Limits] = []


def current() -> Limits:
    """The limits of the build under way in this thread (the defaults outside a build)."""
    limits = _current.get()
    if limits is None:
        if not _DEFAULT:
            _DEFAULT.append(Limits())
        limits = _DEFAULT[0]
    return limits


@contextlib.contextmanager
def applied(limits: Limits | None):
    """Make ``limits`` the current ones within the block (in this thread)."""
    token = _current.set(limits)
    try:
        yield
    finally:
        _current.reset(token)


_UNITS = {"": 1, "K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}


def parse_bytes(text: int | str) -> int:
    """A number of bytes: a whole number, optionally with K, M, G or T (powers of 1024)."""
    if isinstance(text, int) and not isinstance(text, bool):
        value = text
    else:
        m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([KMGT]?)i?B?\s*", str(text), re.I)
        if not m:
            raise LimitError(f'"{text}" is not an amount of memory (such as 512M or 2G)')
        value = int(float(m.group(1)) * _UNITS[m.group(2).upper()])
    if value < 1:
        raise LimitError(f'"{text}" is not an amount of memory > 0')
    return value


def format_bytes(n: float) -> str:
    """Bytes as a short text with a binary unit: ``3.6 TB``."""
    for unit in ("bytes", "KB", "MB", "GB", "TB", "PB"):
        if n < 1024 or unit == "PB":
            return f"{n:.0f} {unit}" if unit == "bytes" else f"{n:.1f} {unit}"
        n /= 1024
    return f"{n} bytes"


def check_shape(shape) -> None:
    """A buffer shape: whole numbers >= 0, and no more elements than the memory limit."""
    count = 1
    for d in shape:
        if isinstance(d, bool) or not isinstance(d, int):
            try:
                whole = int(d) == d
            except (TypeError, ValueError, OverflowError):
                whole = False
            if not whole:
                raise LimitError(f"the size {_dims(shape)} has a dimension that is not a "
                                 f"whole number: {d!r}")
            d = int(d)
        if d < 0:
            raise LimitError(f"the size {_dims(shape)} has a negative dimension")
        count *= d
    if count * BYTES_PER_ELEMENT > current().max_memory:      # the message only then
        check_bytes(count * BYTES_PER_ELEMENT, f"a buffer of size {_dims(shape)}")


def check_bytes(nbytes: int, what: str) -> None:
    limit = current().max_memory
    if nbytes > limit:
        raise LimitError(f"{what}: {format_bytes(nbytes)} is more than the memory limit of "
                         f"{format_bytes(limit)} (set with --max-memory or max_memory=)")


def max_modules() -> int:
    """The most modules a model may have: as many as the memory limit can build (about
    BYTES_PER_MODULE each, besides their buffers)."""
    return current().max_memory // BYTES_PER_MODULE


def check_module_count(count: int, growing: bool = False) -> None:
    """Refuse a model of more modules than ``max_modules()``, before they are built
    (``growing``: counted while group files add theirs, so there are more still)."""
    most = max_modules()
    if count > most:
        raise LimitError(f"the model has {'more than ' * growing}{count - growing} modules; "
                         f"the memory limit of {format_bytes(current().max_memory)} can "
                         f"build at most {most} (about {format_bytes(BYTES_PER_MODULE)} "
                         f"each; set with --max-memory or max_memory=)")


def max_elements() -> int:
    """The most elements one buffer may have."""
    return current().max_memory // BYTES_PER_ELEMENT


def _dims(shape) -> str:
    return "x".join(str(d) for d in shape) or "()"


class Expansion:
    """Counts what resolving one value costs (lookups and length), per thread."""
    _state = threading.local()

    @classmethod
    def start(cls) -> None:
        cls._state.lookups = 0

    @classmethod
    def step(cls, length: int) -> None:
        """One variable looked up; the value has grown to ``length`` characters."""
        limits = current()
        lookups = getattr(cls._state, "lookups", 0) + 1
        cls._state.lookups = lookups
        if lookups > limits.max_lookups:
            raise LimitError(f"resolving the value takes more than {limits.max_lookups} "
                             f"variable lookups")
        if length > limits.max_expansion:
            raise LimitError(f"the value grows longer than {limits.max_expansion} characters "
                             f"as its variables are resolved")
