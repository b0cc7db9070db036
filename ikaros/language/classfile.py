"""Reading an .ikc class file into a ClassDescription."""
from __future__ import annotations

import os

from ..description import (ClassDescription, InputSpec, OutputSpec, ParameterSpec,
                           SIZE_RULE_KEYS, STATE_TYPES, StateSpec, canonical_type,
                           alias_rule, dynamic_rule)
from .diagnostics import warn_at
from .node import Node
from .reader import read_file
from .values import ValueError_, parse_bool, parse_int, parse_number


def _flag(node: Node, key: str) -> bool:
    value = node.get(key)
    if value is None or value == "":
        return False
    try:
        return parse_bool(value)
    except ValueError_ as e:
        raise node.error(f"{key}: {e}") from None


def options_of(node: Node) -> list[str]:
    """Options from ``options="a,b"`` (Ikaros 3) or ``values="a/b"`` (Ikaros 2)."""
    if node.get("options"):
        return [o.strip() for o in node.get("options").split(",") if o.strip()]
    if node.get("values"):
        return [o.strip() for o in node.get("values").split("/") if o.strip()]
    return []


def parameter_spec(node: Node) -> ParameterSpec:
    """A <parameter> element of a class (or of a group) as a ParameterSpec."""
    name = node.get("name")
    if not name:
        raise node.error("a parameter needs a name")
    options = options_of(node)
    declared = node.get("type")
    ptype = canonical_type(declared)
    if declared and ptype is None:
        raise node.error(f'unknown parameter type "{declared}"')
    if ptype is None:
        ptype = "list" if options else "number"
    if options and ptype == "int":
        ptype = "list"
    bounds = (_bound(node, "min"), _bound(node, "max"))
    shape = node.get("shape") or node.get("size") or None
    if shape is not None and ptype not in ("matrix", "array"):
        raise node.error(f'shape="{shape}" is for matrix parameters, not type "{ptype}"')
    return ParameterSpec(name, ptype, node.get("default"), node.get("description", ""),
                         options, node.get("control"),
                         bounds if bounds != (None, None) else None, shape=shape)


def _bound(node: Node, key: str) -> float | None:
    """The ``min`` or ``max`` of a parameter element (Ikaros 3), or None."""
    text = node.get(key)
    if text is None or not text.strip():
        return None
    try:
        return parse_number(text)
    except ValueError_ as e:
        raise node.error(f"{key}: {e}") from None


def _scalar_default(node: Node, stype: str):
    """A scalar state's ``default``, read strictly by its type (Ikaros 3 refuses "12garbage"
    for an int and "maybe" for a bool)."""
    text = node.get("default")
    if text is None or text == "":
        return {"float": 0.0, "double": 0.0, "int": 0, "bool": False, "string": ""}[stype]
    if stype == "string":
        return text
    try:
        if stype == "int":
            return parse_int(text)
        if stype == "bool":
            return parse_bool(text)
        return parse_number(text)
    except ValueError_ as e:
        raise node.error(f"default {e}") from None


def state_spec(node: Node) -> StateSpec:
    """A <state> element of a class (Ikaros 3): a matrix with a shape, or a scalar."""
    name = node.get("name")
    if not name or not name.isidentifier():
        raise node.error(f'a state needs a name that is an identifier, not "{name or ""}"')
    stype = (node.get("type") or "matrix").strip().lower()
    if stype not in STATE_TYPES:
        raise node.error(f'state "{name}": unknown type "{stype}" (use one of '
                         f'{", ".join(STATE_TYPES)})')
    _flag(node, "persistent")       # checked; every state item is kept (docs/language.md)
    if stype == "matrix":
        rule = {k: node.get(k) for k in SIZE_RULE_KEYS if node.get(k) not in (None, "")}
        if not rule:
            raise node.error(f'state "{name}": a matrix state needs a shape')
        return StateSpec(name, stype, None, node.get("description", ""), rule)
    return StateSpec(name, stype, _scalar_default(node, stype), node.get("description", ""))


def description_from_node(root: Node, expected_name: str | None = None) -> ClassDescription:
    """The ClassDescription declared by a <class> element."""
    name = root.get("name") or expected_name
    if not name:
        raise root.error("a class needs a name")
    text = root.get("description", "")
    for d in root.elements("description"):
        if d.text:
            text = d.text
    desc = ClassDescription(name, " ".join(text.split()), source=root.file or "")
    desc.internal = _flag(root, "internal")
    for p in root.elements("parameter"):
        desc.parameters.append(parameter_spec(p))
    for i in root.elements("input"):
        if not i.get("name"):
            raise i.error("an input needs a name")
        desc.inputs.append(InputSpec(i.get("name"), i.get("description", ""),
                                     _flag(i, "optional"), _flag(i, "flatten"),
                                     _flag(i, "stack"), i.get("size"),
                                     _flag(i, "use_label")))
    for o in root.elements("output"):
        if not o.get("name"):
            raise o.error("an output needs a name")
        rule = {k: o.get(k) for k in SIZE_RULE_KEYS if o.get(k) not in (None, "")}
        dynamic, capacity = _flag(o, "dynamic"), o.get("capacity")
        alias = o.get("alias")
        wrong = dynamic_rule(dynamic, capacity, rule) or alias_rule(alias, dynamic, rule)
        if wrong:
            raise o.error(f'output "{o.get("name")}": {wrong}')
        if dynamic:
            rule["capacity"] = capacity
        if alias is not None:
            rule["alias"] = alias
        desc.outputs.append(OutputSpec(o.get("name"), o.get("description", ""), rule,
                                       _flag(o, "optional"), _flag(o, "persistent"),
                                       dynamic=dynamic))
    taken = {p.name for p in desc.inputs + desc.outputs}
    for st in root.elements("state"):
        spec = state_spec(st)
        if spec.name in taken:
            raise st.error("this name is declared twice (as state, input or output); a state "
                           "item is bound to one variable")
        taken.add(spec.name)
        desc.states.append(spec)
    views = list(root.elements("view"))
    if views:
        desc.view = views[0]
    return desc


def read_class_file(path: str) -> ClassDescription:
    """Read an .ikc file (a name that differs from the file name is a warning)."""
    root = read_file(path)
    if root.tag not in ("class", "group"):      # Ikaros 3 class files may have <group>
        raise root.error(f"the root element is <{root.tag}> but must be <class>")
    stem = os.path.splitext(os.path.basename(path))[0]
    declared = root.get("name")
    if declared and declared != stem:
        warn_at(root, f'declared class name "{declared}" does not match the file name '
                      f'"{stem}"; using "{stem}"')
    desc = description_from_node(root, stem)
    desc.name = stem
    return desc

