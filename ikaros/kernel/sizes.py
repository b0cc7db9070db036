"""Output size rules: the Ikaros 2 ``size_*`` attributes and Ikaros 3 ``shape`` expressions."""
from __future__ import annotations

import functools
import math
import re

import numpy as np

from ..description import OutputSpec
from ..language.diagnostics import warn_at
from ..language.expressions import ExpressionError, evaluate_arithmetic
from ..language.values import format_number
from .scope import VariableError, substitute
from .tree import ModuleInstance

_REFERENCE = re.compile(
    r"([A-Za-z_][\w\-]*)\.(shape|rows|cols|size_x|size_y|size_z|size|rank)(\[[^\]]*\])?")
_PARAM = re.compile(r"@([A-Za-z_]\w*)")

WAIT = None   # a rule that cannot be evaluated yet
# rules that size an output from parameters; an element's size="..." or shape="..." (Ikaros 3)
# replaces them when the class has no parameter of that name
_PARAMETER_SIZED = frozenset(("size_param", "size_param_x", "size_param_y"))


class SizeError(Exception):
    """A size rule that can never give a shape; the caller names the output."""


def _param_number(inst: ModuleInstance, name: str):
    value = inst.values.get(name)
    spec = inst.module.description.parameter(name) if inst.module else None
    if spec is not None and spec.type == "list" and spec.options:
        return spec.options.index(value)
    return value


def _int_param(inst: ModuleInstance, name: str):
    """A parameter that gives a size, or None when it has no value."""
    if not inst.has_value.get(name):
        return None
    value = _param_number(inst, name)
    try:
        return int(value)
    except (TypeError, ValueError):
        raise SizeError(f'parameter "{name}" = {value!r} is not a size') from None


def _literal(inst: ModuleInstance, text: str) -> int:
    try:
        return int(evaluate_arithmetic(_substitute(inst, text)))
    except (ExpressionError, VariableError) as e:
        raise SizeError(str(e)) from None


def _substitute(inst: ModuleInstance, text: str) -> str:
    """Replace @p by the module's parameter values (else by variables in scope)."""
    def one(m):
        name = m.group(1)
        if name in inst.values:
            value = _param_number(inst, name)
            if isinstance(value, str):          # a string parameter: a size list ("3,4")
                return value
            if isinstance(value, np.ndarray):
                return ",".join(format_number(v) for v in value.reshape(-1))
            return format_number(float(value))
        return substitute("@" + name, inst)
    return _PARAM.sub(one, text)


def rule_shape(inst: ModuleInstance, spec: OutputSpec, input_shapes: dict,
               partial: bool = False) -> tuple | None:
    """The shape an output's rule gives now, or None (WAIT) when its inputs are not sized yet.

    Rules are tried in the Ikaros 2 order; the first that applies wins. With ``partial``, a
    ``size_set`` rule uses the inputs that are sized (how a loop through a delay gets its
    size from the one input that comes from outside the loop).
    """
    rule = spec.rule
    if len(rule) == 1 and "size_set" in rule:      # the most common rule, alone
        return _size_set(rule["size_set"], input_shapes, partial, inst)
    if inst.shape_attribute is not None and not _PARAMETER_SIZED.isdisjoint(rule):
        return shape_expression(inst, inst.shape_attribute, input_shapes)
    if "size_param_x" in rule or "size_param_y" in rule:
        x = _int_param(inst, rule["size_param_x"]) if "size_param_x" in rule else None
        y = _int_param(inst, rule["size_param_y"]) if "size_param_y" in rule else None
        if x is not None and y is not None:
            return (y, x)
        if x is not None and "size_param_y" not in rule:
            return (x,)
    if "size_param" in rule:
        n = _int_param(inst, rule["size_param"])
        if n is not None:
            return (n,)
    if "size_x" in rule or "size_y" in rule:
        return _axes(inst, rule, input_shapes)
    if "size" in rule:
        return shape_expression(inst, rule["size"], input_shapes)
    if "size_set" in rule:
        return _size_set(rule["size_set"], input_shapes, partial, inst)
    if "size_set_x" in rule or "size_set_y" in rule:
        return _axes(inst, rule, input_shapes)
    if "shape" in rule:
        return shape_expression(inst, rule["shape"], input_shapes)
    if "capacity" in rule:                      # a dynamic output: its largest shape
        return shape_expression(inst, rule["capacity"], input_shapes)
    return WAIT


def _size_set(text: str, input_shapes: dict, partial: bool,
              inst: ModuleInstance) -> tuple | None:
    """The largest of the named inputs (most elements, then highest rank); inputs of
    different sizes are a warning, as in Ikaros 2."""
    shapes = []
    for name in _input_names(text):
        if name not in input_shapes:
            raise SizeError(f'size_set names "{name}", which is not an input')
        shape = input_shapes[name]
        if shape is None:
            if partial:
                continue
            return WAIT
        if shape != ():
            shapes.append(shape)
    if not shapes:
        if partial:
            return WAIT
        raise SizeError(f"none of the inputs {', '.join(_input_names(text))} is connected")
    if len(shapes) == 1 or all(s == shapes[0] for s in shapes):
        return shapes[0]        # what max would give, without the key calls
    largest = max(shapes, key=lambda s: (math.prod(s), len(s)))
    warn_at(inst.node, f'size_set="{text}": the inputs have different sizes '
                       f'({", ".join(str(s) for s in shapes)}); the largest, {largest}, is used')
    return largest


@functools.lru_cache(maxsize=None)
def _input_names(text: str) -> tuple[str, ...]:
    """The inputs a ``size_set`` rule names."""
    return tuple(n.strip() for n in text.split(",") if n.strip())


def _axes(inst: ModuleInstance, rule: dict, input_shapes: dict) -> tuple | None:
    """Width and height set separately: each from its literal (``size_x``) or else from the
    number of elements of an input (``size_set_x``). One axis alone gives a vector for x and
    a column for y."""
    sizes = {}
    for axis in ("x", "y"):
        if f"size_{axis}" in rule:
            sizes[axis] = _literal(inst, rule[f"size_{axis}"])
        elif f"size_set_{axis}" in rule:
            shape = input_shapes.get(rule[f"size_set_{axis}"].strip())
            if shape is None:
                return WAIT
            sizes[axis] = math.prod(shape) if shape != () else 0
    x, y = sizes.get("x"), sizes.get("y")
    if x is not None and y is not None:
        return (y, x)
    return (x,) if x is not None else (y, 1)


def shape_expression(inst: ModuleInstance, text: str, input_shapes: dict) -> tuple | None:
    """Evaluate an Ikaros 3 shape expression such as ``INPUT.shape`` or
    ``optional(INPUT.size_z), INPUT.rows-@k+1, 3``."""
    waiting = False

    def reference(m):
        nonlocal waiting
        name, what, index = m.group(1), m.group(2), m.group(3)
        if name in input_shapes:
            shape = input_shapes[name]
            if shape is None:
                waiting = True
                return "0"
        elif name in inst.values and isinstance(inst.values[name], np.ndarray):
            shape = inst.values[name].shape
        else:
            raise SizeError(f'"{name}" is neither an input nor a matrix parameter')
        shape = list(shape)
        if what == "shape":
            if index:
                body = index[1:-1]
                parts = body.split(":")
                picked = shape[int(parts[0])] if len(parts) == 1 else \
                    shape[int(parts[0] or 0):int(parts[1]) if parts[1] else None]
                shape = picked if isinstance(picked, list) else [picked]
            return ",".join(str(s) for s in shape) if shape else "0"
        if what == "rank":
            return str(len(shape))
        if what == "size":
            return str(math.prod(shape) if shape else 0)
        from_end = {"cols": 1, "size_x": 1, "rows": 2, "size_y": 2, "size_z": 3}[what]
        return str(shape[-from_end]) if len(shape) >= from_end else "1"

    text = _REFERENCE.sub(reference, text)
    if waiting:
        return WAIT
    text = _substitute(inst, text)
    dims: list[int] = []
    for item in _split_top_level(text):
        optional = False
        m = re.fullmatch(r"\s*optional\((.*)\)\s*", item)
        if m:
            item, optional = m.group(1), True
        parts = [p for p in item.split(",")] if "," in item else [item]
        for part in parts:
            try:
                value = whole_dimension(evaluate_arithmetic(part))
            except ExpressionError as e:
                raise SizeError(f'shape "{text}": {e}') from None
            if value == 0 and optional:
                continue
            if value <= 0:
                raise SizeError(f'shape "{text}" gives a dimension of {value}')
            dims.append(value)
    return tuple(dims)


def whole_dimension(value: float) -> int:
    """A dimension from the value of its expression: cut down to a whole number, except
    that a value within a millionth of one is that number (``0.29*100`` is 29, not 28)."""
    if not math.isfinite(value):
        raise ExpressionError(f"{value} is not a size")
    nearest = round(value)
    return int(nearest) if abs(value - nearest) <= 1e-6 else int(value)


def _split_top_level(text: str) -> list[str]:
    items, depth, current = [], 0, ""
    for ch in text:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        if ch == "," and depth == 0:
            items.append(current)
            current = ""
        else:
            current += ch
    items.append(current)
    return [i for i in items if i.strip()]
