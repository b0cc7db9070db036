"""Class descriptions: what a module class declares (parameters, inputs, outputs).

A description is produced either from a Python module class or from an ``.ikc`` file; both
give the same structure, which the kernel, the command line, the editor and the docs read.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

PARAMETER_TYPES = ("number", "int", "bool", "string", "list", "array", "matrix")

# Spellings found in existing .ikc files, mapped onto the types above.
TYPE_ALIASES = {
    "float": "number", "double": "number", "rate": "number", "number": "number",
    "int": "int", "integer": "int",
    "bool": "bool", "boolean": "bool",
    "string": "string", "text": "string", "str": "string",
    "list": "list", "options": "list",
    "array": "array", "matrix": "matrix",
}


def canonical_type(name: str | None) -> str | None:
    """The canonical parameter type for a spelling found in a class file, or None."""
    if name is None or name == "":
        return None
    return TYPE_ALIASES.get(name.strip().lower())


@dataclass
class ParameterSpec:
    """One parameter of a class."""
    name: str
    type: str = "number"
    default: Any = None          # the default as written (a string), or a Python value
    description: str = ""
    options: list[str] = field(default_factory=list)
    control: str | None = None   # a UI hint: menu, checkbox, slider, textedit
    range: tuple | None = None   # (lowest, highest) a number may be; None for no bound
    finite: bool = True          # whether nan and inf are refused
    file: bool = False           # whether the value names a file or folder
    shape: str | None = None     # a matrix's fixed shape expression (Ikaros 3 ``shape``)
    fixed: bool = False          # whether a change while the model runs is refused
    default_v3: Any = None       # the default in a file of dialect 3, where Ikaros 3 changed it

    def to_dict(self) -> dict:
        d = {"name": self.name, "type": self.type, "default": _plain(self.default),
             "description": self.description}
        if self.options:
            d["options"] = list(self.options)
        if self.control:
            d["control"] = self.control
        if self.range:
            d["range"] = list(self.range)
        if not self.finite:
            d["finite"] = False
        if self.file:
            d["file"] = True
        if self.shape:
            d["shape"] = self.shape
        if self.fixed:
            d["fixed"] = True
        if self.default_v3 is not None:
            d["default_v3"] = _plain(self.default_v3)
        return d


@dataclass
class InputSpec:
    """One input of a class."""
    name: str
    description: str = ""
    optional: bool = False
    flatten: bool = False
    stack: bool = False
    size: str | None = None      # a fixed shape expression (Ikaros 3 ``size``)
    use_label: bool = False      # the input takes the label of its one labelled connection

    def to_dict(self) -> dict:
        d = {"name": self.name, "description": self.description, "optional": self.optional}
        for key in ("flatten", "stack", "use_label"):
            if getattr(self, key):
                d[key] = True
        if self.size:
            d["size"] = self.size
        return d


# The Ikaros 2 size attributes of an output, in the order they are tried.
SIZE_RULE_KEYS = ("size_param_x", "size_param_y", "size_param", "size_x", "size_y", "size",
                  "size_set", "size_set_x", "size_set_y", "shape")


@dataclass
class OutputSpec:
    """One output of a class with its size rule (Ikaros 2 ``size_*`` or Ikaros 3 ``shape``)."""
    name: str
    description: str = ""
    rule: dict[str, str] = field(default_factory=dict)
    optional: bool = False
    persistent: bool = False     # Ikaros 3 ``persistent``: every output is kept in state files
    private: bool = False        # a matrix <state>: sized and kept like an output, not connectable
    dynamic: bool = False   # Ikaros 3 dynamic="yes": the shape changes at run time; the
                            # rule is then {"capacity": ...}, the largest shape

    def to_dict(self) -> dict:
        d: dict[str, Any] = {"name": self.name, "description": self.description}
        d.update(self.rule)
        for key in ("optional", "persistent", "private", "dynamic"):
            if getattr(self, key):
                d[key] = True
        return d

    def rule_text(self) -> str:
        """A short human-readable form of the size rule."""
        return ", ".join(f"{k}={v}" for k, v in self.rule.items()) or "set by the module"


# The types of a <state> item: a matrix, or a scalar of one of these (Ikaros 3 names).
STATE_TYPES = ("matrix", "float", "double", "int", "bool", "string")


@dataclass
class StateSpec:
    """One state item a class declares (Ikaros 3 ``<state>``): private, kept by save, load
    and reset of the state (whether ``persistent`` or not) but not connectable. A matrix is sized by ``rule`` like an
    output; a scalar is an attribute of the module that starts at ``default``."""
    name: str
    type: str = "float"
    default: Any = None          # a scalar's first value (a Python value of the type)
    description: str = ""
    rule: dict[str, str] = field(default_factory=dict)

    def to_dict(self) -> dict:
        d = {"name": self.name, "type": self.type, "description": self.description}
        if self.type == "matrix":
            d.update(self.rule)
        else:
            d["default"] = self.default
        return d


def dynamic_rule(dynamic: bool, capacity: str | None, rule: dict) -> str | None:
    """Why a dynamic output's declaration is wrong (None when it is right): ``dynamic``
    needs a ``capacity`` and no other size rule, and ``capacity`` needs ``dynamic``."""
    if dynamic and not capacity:
        return "a dynamic output needs a capacity (its largest shape)"
    if capacity and not dynamic:
        return 'capacity is for dynamic outputs (dynamic="yes")'
    if dynamic and rule:
        return f"a dynamic output is sized by its capacity, not by {', '.join(rule)}"
    return None


_ALIAS = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)((?:\[\d+\])*)")


def parse_alias(text: str) -> tuple[str, tuple[int, ...]] | None:
    """An output alias (Ikaros 3 ``alias="OUTPUT[0]"``) as (output name, indices), or None
    when it is not one: an output name with zero or more single whole-number indices."""
    m = _ALIAS.fullmatch(text.replace(" ", ""))
    if m is None:
        return None
    return m.group(1), tuple(int(i) for i in re.findall(r"\d+", m.group(2)))


def alias_rule(alias: str | None, dynamic: bool, rule: dict) -> str | None:
    """Why an alias output's declaration is wrong (None when it is right or not an alias):
    an alias is an output name with single indices, and has no size rule of its own."""
    if alias is None:
        return None
    if parse_alias(alias) is None:
        return (f'alias "{alias}" must name another output of the module, with single '
                f'indices only (OUTPUT or OUTPUT[0])')
    if rule or dynamic:
        return "an alias takes its shape from the output it views: it can not also have a " \
               "shape, size or capacity"
    return None


@dataclass
class ClassDescription:
    """Everything a class declares; the same whether it comes from Python or an .ikc file."""
    name: str
    description: str = ""
    parameters: list[ParameterSpec] = field(default_factory=list)
    inputs: list[InputSpec] = field(default_factory=list)
    outputs: list[OutputSpec] = field(default_factory=list)
    states: list[StateSpec] = field(default_factory=list)
    source: str = ""             # the file the description was read from
    script: str = ""             # the Python script that is the class's code (python=)
    view: Any = None             # a default view (a Node) carried by the class, if any
    internal: bool = False

    def parameter(self, name: str) -> ParameterSpec | None:
        return next((p for p in self.parameters if p.name == name), None)

    def input(self, name: str) -> InputSpec | None:
        return next((p for p in self.inputs if p.name == name), None)

    def output(self, name: str) -> OutputSpec | None:
        return next((p for p in self.outputs if p.name == name), None)

    def to_dict(self) -> dict:
        return {
            "name": self.name,
            "description": self.description,
            "parameters": [p.to_dict() for p in self.parameters],
            "inputs": [p.to_dict() for p in self.inputs],
            "outputs": [p.to_dict() for p in self.outputs],
            **({"states": [s.to_dict() for s in self.states]} if self.states else {}),
            "source": self.source,
            **({"script": self.script} if self.script else {}),
        }

    def to_text(self) -> str:
        """The description as readable text, for ``ikaros --class NAME``."""
        lines = [self.name, "=" * len(self.name), plain_text(self.description) or "(no description)",
                 ""]
        lines.append("Parameters:" if self.parameters else "Parameters: none")
        for p in self.parameters:
            opts = f" options={'/'.join(p.options)}" if p.options else ""
            if p.range:
                low, high = ("" if v is None else f"{v:g}" for v in p.range)
                opts += f", range {low}..{high}"
            if p.shape:
                opts += f", shape {p.shape}"
            if p.fixed:
                opts += ", fixed while running"
            lines.append(f"  {p.name} ({p.type}, default {_plain(p.default)!r}{opts}): "
                         f"{plain_text(p.description)}")
        lines.append("Inputs:" if self.inputs else "Inputs: none")
        for i in self.inputs:
            flags = [f for f in ("optional", "flatten", "stack", "use_label") if getattr(i, f)]
            lines.append(f"  {i.name}{' (' + ', '.join(flags) + ')' if flags else ''}: "
                         f"{plain_text(i.description)}")
        lines.append("Outputs:" if self.outputs else "Outputs: none")
        for o in self.outputs:
            lines.append(f"  {o.name} [{o.rule_text()}]: {plain_text(o.description)}")
        if self.states:
            lines.append("State:")
        for st in self.states:
            what = ", ".join(f"{k}={v}" for k, v in st.rule.items()) \
                if st.type == "matrix" else f"default {st.default!r}"
            lines.append(f"  {st.name} ({st.type}, {what}): {plain_text(st.description)}")
        if self.source:
            lines.append(f"Source: {self.source}")
        if self.script:
            lines.append(f"Script: {self.script} (runs in a worker process per module)")
        return "\n".join(lines)


_CODE = re.compile(r"``([^`]+)``|`([^`]+)`")


def plain_text(text: str) -> str:
    """A description as the terminal shows it: its ``code`` and `code` markup as the bare
    words (the web UI shows them as code)."""
    return _CODE.sub(lambda m: m.group(1) or m.group(2), text)


def _plain(value: Any) -> Any:
    """A JSON-friendly form of a default value."""
    if hasattr(value, "tolist"):
        return value.tolist()
    return value
