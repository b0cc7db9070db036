"""Variables (``@name``, ``{expr}``) and parameter lookup in the instance tree."""
from __future__ import annotations

import re

import numpy as np

from ..description import ParameterSpec
from ..language.diagnostics import warn, warn_at
from ..language.expressions import ExpressionError, evaluate_arithmetic, is_arithmetic
from ..language.values import (ValueError_, format_number, parse_bool, parse_int,
                               parse_matrix, parse_number)
from ..limits import Expansion, LimitError, current as current_limits
from .tree import Group, ModuleInstance, Scope, find_component, group_of

MAX_DEPTH = 64
_VAR = re.compile(r"@([A-Za-z_]\w*)")
_BRACES = re.compile(r"\{([^{}]*)\}")
_PATH_CHARS = re.compile(r"[\w.\-]*$")
_NAME_OR_PATH = re.compile(r"\.?[A-Za-z_][\w\-]*(\.[A-Za-z_][\w\-]*)*")


class VariableError(Exception):
    """A variable that cannot be resolved; the caller names the element."""


class UndefinedVariable(VariableError):
    """A variable that no enclosing element defines."""


def lookup_variable(name: str, scope, depth: int = 0, own: str | None = None) -> str:
    """The value of ``@name`` seen from a scope: its own attributes, then enclosing groups.
    A value that itself holds variables is resolved where it is defined. In the value of
    attribute ``own``, ``@own`` means the same name further out (``factor="@factor"``).
    Last, the top-level settings' defaults (``@tick_duration`` when no group sets it)."""
    outermost = scope
    for s in scope.chain():
        outermost = s
        if name in s.attrs and not (name == own and s is scope):
            raw = s.attrs[name]
            value = substitute(raw, s, depth + 1, own=name)
            if "@" in raw and _has_operator(value) and is_arithmetic(value):
                # arithmetic with variables is computed where it is defined, so that
                # {@c*1000} with c="@b+2" multiplies the sum
                try:
                    return format_number(evaluate_arithmetic(value))
                except ExpressionError as e:
                    raise VariableError(f'"{raw}": {e}') from None
            return value
    default = getattr(outermost, "defaults", {}).get(name)
    if default is not None:
        return default
    raise UndefinedVariable(f'Variable "@{name}" not defined.')


def substitute(text: str, scope, depth: int = 0, own: str | None = None) -> str:
    """Replace ``{expr}`` and ``@name`` in a value, resolving each in ``scope``.

    ``Path.@name`` reads attribute ``name`` of the component at ``Path`` when that component
    has it (Ikaros 3 data blocks): at the end of the value that attribute's value is the
    result, inside a path it is the next segment (``outer.@which.@value``). Otherwise
    ``@name`` is looked up from ``scope`` and the path is kept (Ikaros 2 path variables).
    """
    if "@" not in text and "{" not in text:
        return text
    if depth > MAX_DEPTH:
        raise VariableError(f'variables nest deeper than {MAX_DEPTH} levels in "{text}"')
    if depth == 0:
        Expansion.start()
        if "{" in text:
            _check_braces(text)
    while True:
        m = _BRACES.search(text)
        if not m:
            break
        inner = substitute(m.group(1), scope, depth + 1, own).strip()
        if is_arithmetic(inner):
            try:
                inner = format_number(evaluate_arithmetic(inner))
            except ExpressionError as e:
                raise VariableError(str(e)) from None
        elif _NAME_OR_PATH.fullmatch(inner):
            inner = _path_value(inner, scope, depth)
        text = text[:m.start()] + inner + text[m.end():]
        _spend(len(text))
    if "}" in text or "{" in text:
        raise VariableError(f'unmatched brace in "{text}"')
    out = ""
    pos = 0
    for m in _VAR.finditer(text):
        out += text[pos:m.start()]
        pos = m.end()
        name = m.group(1)
        at_end = pos == len(text) or not re.match(r"[\w.]", text[pos])
        prefix = _PATH_CHARS.search(out).group(0) if out.endswith(".") else ""
        if prefix:
            start = group_of(scope)
            target = _data_element(start, prefix[:-1]) if start and prefix[:-1] else None
            if target is not None and name in target.attrs:
                value = substitute(target.attrs[name], target, depth + 1)
                # at the end the attribute's value is the result; inside a path it is the
                # next segment (``outer.@which.@value``)
                out = (out[:len(out) - len(prefix)] if at_end else out) + value
                continue
        try:
            out += lookup_variable(name, scope, depth, own)
            _spend(len(out))
        except UndefinedVariable:
            if text.strip() != m.group(0):
                raise
            # Ikaros 2 reads an undefined variable as an empty value (a group file loaded
            # on its own); where an empty value can not be used, that is the error.
            message = f'variable "@{name}" is not defined; read as an empty value'
            node = getattr(scope, "node", None)
            if node is not None:
                warn_at(node, message)
            else:
                warn(message)
    return out + text[pos:]


def _path_value(text: str, scope, depth: int) -> str:
    """Ikaros 3 ``{name}`` and ``{Path.To.Element.name}`` (``{.Top.Block.x}``): the value
    of a variable, or of an attribute of the element at a path."""
    path, dot, name = text.rpartition(".")
    if not dot:
        return lookup_variable(name, scope, depth)
    start = group_of(scope)
    target = _data_element(start, path) if start is not None and path else \
        (start.top() if start is not None else None)
    if target is None or name not in target.attrs:
        raise VariableError(f'"{text}" names no element attribute')
    return substitute(target.attrs[name], target, depth + 1)


def _data_element(start: Group, path: str):
    """The group or module at a path, or else another element with that name (a data
    block such as ``<data name="Arm" x="1"/>``) as a scope."""
    found = find_component(start, path)
    if found is not None:
        return found
    parent_path, _, name = path.rpartition(".")
    parent = find_component(start, parent_path) if parent_path else \
        (start.top() if path.startswith(".") else start)
    if not isinstance(parent, Group):
        return None
    for element in parent.node.elements():
        if element.attrs.get("name") == name and element.tag not in ("module", "group"):
            return Scope(element, parent)
    return None


def _check_braces(text: str) -> None:
    """Refuse ``{...}`` nested deeper than the expression limit (each level is a pass)."""
    limit = current_limits().max_expression_depth
    depth = 0
    for ch in text:
        if ch == "{":
            depth += 1
            if depth > limit:
                raise VariableError(f"braces nest deeper than {limit} levels")
        elif ch == "}":
            depth -= 1


def _spend(length: int) -> None:
    """Count one step of resolving a value (see ikaros.limits.Expansion)."""
    try:
        Expansion.step(length)
    except LimitError as e:
        raise VariableError(str(e)) from None


def _has_operator(text: str) -> bool:
    return bool(re.search(r"[+*/]|(?<=[\w)])\s*-", text))


def lookup_parameter(inst: ModuleInstance, name: str):
    """Find the raw value of a module's parameter.

    Returns (text, scope, from_default) or None. The module's own attribute first; then each
    enclosing group outward, where a renaming ``<parameter target=...>`` (for this module,
    then for all), a qualified attribute (``Path.To.Module.p``, then ``Module.p``, which
    reaches a module of that name at any depth) and a plain attribute ``p`` are looked at in
    that order; then a renaming's default.
    """
    if name in inst.attrs:
        return inst.attrs[name], inst, False
    renamed_default = None
    seen = set()
    group = inst.parent
    while group is not None:
        relative = inst.path[len(group.path) + 1:] if group.path else inst.path
        key = (id(group), name)
        if key in seen:
            raise VariableError(f'parameter renaming loops on "{name}"')
        seen.add(key)
        rename = _renaming(group, f"{relative}.{name}") or \
            _renaming(group, f"{inst.name}.{name}") or _renaming(group, name)
        if rename is not None:
            new = rename.get("name")
            if not new or new == name:
                raise VariableError(f'<parameter target="{rename.get("target")}"> maps '
                                    f'"{name}" onto itself')
            if renamed_default is None and rename.get("default") is not None:
                renamed_default = (rename.get("default"), group)
            name = new
            continue                       # look the new name up, starting at this group
        qualified = f"{relative}.{name}"
        if qualified in group.attrs:
            return group.attrs[qualified], group, False
        qualified = f"{inst.name}.{name}"        # reaches a module of that name at any depth
        if qualified in group.attrs:
            return group.attrs[qualified], group, False
        if name in group.attrs:
            return group.attrs[name], group, False
        group = group.parent
    if renamed_default is not None:
        return renamed_default[0], renamed_default[1], True
    return None


def _renaming(group: Group, target: str):
    return next((p for p in group.renamings if p.get("target") == target), None)


ZERO = {"number": 0.0, "int": 0, "bool": False, "string": ""}


def convert(text, spec: ParameterSpec, scope, own: str | None = None) -> object:
    """A parameter value of the spec's type from text found in ``scope`` (or a Python value).

    Raises ValueError_ or VariableError with the reason.
    """
    if not isinstance(text, str):
        return from_python(text, spec)
    raw = text
    text = substitute(text, scope, own=own)
    t = spec.type
    if t == "number":
        if spec.options:            # Ikaros 3: a label or an index; the value is the index
            return float(option_index(text, spec))
        return parse_number(text)
    if t == "int":
        return parse_int(text)
    if t == "bool":
        if spec.options:
            return option_index(text, spec) != 0
        return parse_bool(text)
    if t == "list":
        return spec.options[option_index(text, spec)] if spec.options else text
    if t in ("array", "matrix"):
        arr = parse_matrix(text)
        return arr.reshape(-1) if t == "array" else arr
    if "@" in raw and _has_operator(text) and is_arithmetic(text):
        return format_number(evaluate_arithmetic(text))
    return text


def option_index(text: str, spec: ParameterSpec) -> int:
    """The index of an option given by its label or its number."""
    s = str(text).strip()
    if s in spec.options:
        return spec.options.index(s)
    if re.fullmatch(r"\d+", s) and int(s) < len(spec.options):
        return int(s)
    raise ValueError_(f'"{text}" is not one of {"/".join(spec.options)}')


def from_python(value, spec: ParameterSpec):
    """A Python value (a default written in Python, or a value set from code) as the spec's
    type."""
    t = spec.type
    if value is None:
        if t in ("array", "matrix"):
            return np.zeros((0,), dtype=np.float32)
        if t == "list":
            return spec.options[0] if spec.options else ""
        return ZERO[t]
    if isinstance(value, str):
        return convert(value, spec, _EMPTY)
    if t == "number":
        return float(value)
    if t == "int":
        if float(value) != int(value):
            raise ValueError_(f"{value!r} is not an integer")
        return int(value)
    if t == "bool":
        if isinstance(value, (bool, np.bool_)) or value in (0, 1):
            return bool(value)
        raise ValueError_(f"{value!r} is not a boolean")
    if t == "list":
        return spec.options[option_index(str(value), spec)] if spec.options else str(value)
    if t in ("array", "matrix"):
        arr = np.array(value, dtype=np.float32)
        return arr.reshape(-1) if t == "array" else arr
    return str(value)


class _EmptyScope:
    attrs: dict = {}
    parent = None

    def chain(self):
        yield self


_EMPTY = _EmptyScope()
