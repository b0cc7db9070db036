"""The module reference: ``docs/modules.md`` generated from the class descriptions of the
standard library (``ikaros/modules/<category>/<Name>.py`` or ``.ikc``).

Regenerate the file with ``ikaros --modules-doc`` from the repository root; a test fails when
it is out of date.
"""
from __future__ import annotations

import json
import os

from .description import ClassDescription, InputSpec, OutputSpec, ParameterSpec, _plain
from .kernel.classes import STDLIB, stdlib_classes

COMMAND = "ikaros --modules-doc"
DEFAULT_PATH = os.path.join("docs", "modules.md")

# Categories come first in this order; any other category folder follows alphabetically.
CATEGORY_ORDER = ("utility", "coding", "control", "io", "sound", "neural", "brain", "learning",
                  "environment", "robot", "vision")
CATEGORY_TITLES = {"io": "IO", "neural": "Neural network", "brain": "Brain models"}
ROOT_CATEGORY = ""           # a class file directly in ikaros/modules, outside any category

_REPO = os.path.dirname(os.path.dirname(STDLIB))   # the folder that holds the ikaros package


def _under_stdlib(path: str) -> bool:
    if not path or not os.path.isabs(path):
        return False
    stdlib = os.path.realpath(STDLIB)
    return os.path.commonpath([os.path.realpath(path), stdlib]) == stdlib


def standard_classes() -> dict[str, ClassDescription]:
    """{name: description} of every standard-library class, sorted by name: classes whose
    source file is under ``ikaros/modules`` (not user folders or entry points; group files
    and internal classes are left out)."""
    out = {}
    for name, entry in sorted(stdlib_classes().items()):
        if entry.is_group:
            continue
        desc = entry.description()
        if desc.internal or not _under_stdlib(desc.source):
            continue
        out[name] = desc
    return out


def source_path(desc: ClassDescription) -> str:
    """The description's source file relative to the repository, with ``/`` separators,
    e.g. ``ikaros/modules/utility/Scale.py``."""
    rel = os.path.relpath(os.path.realpath(desc.source), os.path.realpath(_REPO))
    return rel.replace(os.sep, "/")


def category(desc: ClassDescription) -> str:
    """The folder under ``ikaros/modules`` that holds the class's source file."""
    rel = os.path.relpath(os.path.realpath(desc.source), os.path.realpath(STDLIB))
    parts = rel.split(os.sep)
    return parts[0] if len(parts) > 1 else ROOT_CATEGORY


def category_key(name: str) -> tuple:
    if name in CATEGORY_ORDER:
        return (0, CATEGORY_ORDER.index(name), name)
    return (1 if name != ROOT_CATEGORY else 2, 0, name)


def category_title(name: str) -> str:
    if name == ROOT_CATEGORY:
        return "Other"
    return CATEGORY_TITLES.get(name, name[:1].upper() + name[1:])


def _anchor(title: str) -> str:
    """The anchor GitHub gives a heading."""
    keep = "".join(c for c in title.lower() if c.isalnum() or c in " -_")
    return keep.replace(" ", "-")


def _cell(text) -> str:
    """Text safe for one Markdown table cell."""
    text = " ".join(str(text).split())
    return text.replace("|", "\\|")


def _code(text: str) -> str:
    text = " ".join(str(text).split()).replace("|", "\\|")
    fence = "``" if "`" in text else "`"
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def _default(value) -> str:
    value = _plain(value)
    if value is None:
        return ""
    if isinstance(value, str):
        return _code(value) if value != "" else '`""`'
    if isinstance(value, (list, tuple, dict)):
        return _code(json.dumps(value))
    return _code(repr(value))


def _parameter_row(p: ParameterSpec) -> str:
    options = ", ".join(_code(o) for o in p.options)
    fixed = " (fixed while the model runs)" if p.fixed else ""
    default = _default(p.default)
    if p.default_v3 is not None:
        default += f" (Ikaros 3: {_default(p.default_v3)})"
    return (f"| {_code(p.name)} | {_cell(p.type)} | {default} | {options} | "
            f"{_cell(p.description + fixed)} |")


def _input_row(i: InputSpec) -> str:
    flags = [f for f in ("optional", "flatten", "stack") if getattr(i, f)]
    if i.size:
        flags.append(f"size {_code(i.size)}")
    return f"| {_code(i.name)} | {', '.join(flags)} | {_cell(i.description)} |"


def _output_row(o: OutputSpec) -> str:
    name = _code(o.name) + (" (optional)" if o.optional else "")
    rule = _code(o.rule_text()) if o.rule else _cell(o.rule_text())
    return f"| {name} | {rule} | {_cell(o.description)} |"


def class_section(desc: ClassDescription, level: int = 3) -> list[str]:
    """The Markdown lines of one class: a heading of ``level``, its description, tables of
    its parameters (with their Ikaros 3 defaults where they differ), inputs and outputs,
    and its source file."""
    lines = [f"{'#' * level} {desc.name}", ""]
    text = " ".join(desc.description.split())
    lines += [text or "*(no description)*", ""]
    lines += _table("Parameters", "| Name | Type | Default | Options | Description |",
                    [_parameter_row(p) for p in desc.parameters], "none")
    lines += _table("Inputs", "| Name | Flags | Description |",
                    [_input_row(i) for i in desc.inputs], "none")
    lines += _table("Outputs", "| Name | Size | Description |",
                    [_output_row(o) for o in desc.outputs], "none (or set by the module in code)")
    lines += [f"Source: `{source_path(desc)}`", ""]
    return lines


def _table(title: str, header: str, rows: list[str], empty: str) -> list[str]:
    """A titled Markdown table, or one line saying there is nothing."""
    if not rows:
        return [f"**{title}:** {empty}", ""]
    rule = "|" + "---|" * (header.count("|") - 1)
    return [f"**{title}**", "", header, rule] + rows + [""]


def module_reference() -> str:
    """The Markdown text of ``docs/modules.md``: every standard-library class grouped by
    category, with its parameters, inputs, outputs and source file."""
    groups: dict[str, list[ClassDescription]] = {}
    for desc in standard_classes().values():
        groups.setdefault(category(desc), []).append(desc)
    order = sorted(groups, key=category_key)
    total = sum(len(v) for v in groups.values())

    lines = [
        "# Standard module library",
        "",
        f"<!-- Generated by `{COMMAND}` (ikaros/docgen.py). Do not edit by hand. -->",
        "",
        f"This file is generated from the class descriptions in `ikaros/modules` by "
        f"`{COMMAND}` (run from the repository root; `{COMMAND} -` prints it instead). "
        f"Do not edit it by hand: change the class's docstring and declarations, then "
        f"regenerate it. `tests/test_module_reference.py` fails when it is out of date.",
        "",
        f"{total} classes in {len(order)} categories. `ikaros --class NAME` prints one "
        f"class's description; `ikaros --classes` lists every class found, including those "
        f"beside a model and in installed packages.",
        "",
        "## Categories",
        "",
        "| Category | Classes | |",
        "|---|---|---|",
    ]
    for cat in order:
        title = category_title(cat)
        names = ", ".join(f"[{d.name}](#{_anchor(d.name)})" for d in groups[cat])
        lines.append(f"| [{title}](#{_anchor(title)}) | {len(groups[cat])} | {names} |")
    lines.append("")
    for cat in order:
        lines += [f"## {category_title(cat)}", "",
                  f"Classes in `ikaros/modules/{cat}/`." if cat != ROOT_CATEGORY
                  else "Classes directly in `ikaros/modules/`.", ""]
        for desc in groups[cat]:
            lines += class_section(desc)
    while lines and lines[-1] == "":
        lines.pop()
    return "\n".join(lines) + "\n"
