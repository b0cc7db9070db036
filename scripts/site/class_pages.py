"""A page per standard class for the documentation site: its description, parameters,
inputs and outputs (``ikaros.docgen``), what Ikaros 2 and Ikaros 3 files give where they
differ (the rows of ``docs/language.md`` that name the class), an example model and a plot
of the class's outputs over that example's first ticks."""
from __future__ import annotations

import contextlib
import glob
import io
import os
import re
import tempfile
import warnings
from dataclasses import dataclass

import numpy as np

import ikaros
from ikaros.description import ClassDescription
from ikaros.docgen import category, category_title, class_section, source_path, \
    standard_classes, category_key

from plots import plot_outputs

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, "examples")
PLOT_TICKS = 60
# IKAROS_SITE_PLOTS="A,B": plot only those classes (a quick build, as the site's test makes);
# unset: every class
ONLY_PLOTS = {n for n in os.environ.get("IKAROS_SITE_PLOTS", "").split(",") if n} or None


@dataclass
class Example:
    """A model that uses the class: its file (relative to the repository) and text."""
    path: str
    text: str
    generated: bool = False


def _uses(text: str, name: str) -> bool:
    return re.search(rf'class\s*=\s*"{re.escape(name)}"', text) is not None


def find_example(name: str, models: dict[str, str]) -> Example | None:
    """``examples/modules/<name>_example.ikg``, else the first example model that uses
    the class."""
    own = f"examples/modules/{name}_example.ikg"
    if own in models:
        return Example(own, models[own])
    for path, text in models.items():
        if _uses(text, name):
            return Example(path, text)
    return None


def generated_example(desc: ClassDescription) -> Example:
    """A model with the class at its defaults and a Constant into each required input (as
    the golden files' mechanical cases are made), for a class no example uses."""
    lines = [f'<group name="{desc.name}_example">']
    for k, inp in enumerate(i for i in desc.inputs if not i.optional):
        data = " ".join(str(v) for v in (k + 1) * np.array([0.25, 0.5, 0.75, 1.0]))
        lines.append(f'    <module class="Constant" name="{inp.name}_source" data="{data}" />')
    lines.append(f'    <module class="{desc.name}" name="{desc.name}" />')
    for inp in (i for i in desc.inputs if not i.optional):
        lines.append(f'    <connection source="{inp.name}_source.OUTPUT" '
                     f'target="{desc.name}.{inp.name}" delay="0" />')
    lines.append("</group>")
    return Example("", "\n".join(lines) + "\n", generated=True)


def record_outputs(path: str, name: str, ticks: int) -> dict[str, np.ndarray] | None:
    """The outputs of the first module of class ``name`` in the model at ``path``, tick by
    tick (ticks, ...), those whose shape stays the same, or None when the model does not run here (a missing device or
    optional package, a file it needs)."""
    quiet = io.StringIO()
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(quiet), \
                contextlib.redirect_stderr(quiet):
            warnings.simplefilter("ignore")
            with ikaros.load(path, quiet=True) as net:
                found = [p for p, inst in net.modules.items() if inst.entry.name == name]
                if not found:
                    return None
                _, outputs = net.ports(found[0])
                rows: dict[str, list] = {o.name: [] for o in outputs}
                for _ in range(ticks):
                    net.step()
                    for o in outputs:
                        rows[o.name].append(net.output(f"{found[0]}.{o.name}"))
                    if net.stopped:
                        break
    except Exception:   # noqa: BLE001: an example that needs what this machine lacks
        return None
    # a dynamic output (a list whose length changes) is left out of the plot
    return {k: np.array(v) for k, v in rows.items()
            if v and np.asarray(v[0]).size and len({np.shape(x) for x in v}) == 1}


def example_and_plot(desc: ClassDescription, models: dict[str, str],
                     images: str) -> tuple[Example | None, str | None]:
    """The example of the class and the file name of its plot under ``images`` (None when
    the example does not run here or its outputs cannot be drawn)."""
    example = find_example(desc.name, models)
    plotted = ONLY_PLOTS is None or desc.name in ONLY_PLOTS
    if example is None:
        example = generated_example(desc)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "example.ikg")
            with open(path, "w", encoding="utf-8") as f:
                f.write(example.text)
            outputs = record_outputs(path, desc.name, PLOT_TICKS)
        if outputs is None:
            return None, None
    elif plotted:
        outputs = record_outputs(os.path.join(ROOT, example.path), desc.name, PLOT_TICKS)
    else:
        return example, None
    if not outputs or not plotted:
        return example, None
    name = f"{desc.name}.svg"
    if not plot_outputs(outputs, os.path.join(images, name), desc.name):
        return example, None
    return example, name


def dialect_rows(language_md: str) -> dict[str, list[str]]:
    """{class name: the table rows of docs/language.md whose first cell names it}."""
    rows: dict[str, list[str]] = {}
    header = None
    for line in language_md.splitlines():
        if not line.startswith("|"):
            header = None
            continue
        if header is None:
            header = line
            continue
        if set(line.replace("|", "").strip()) <= set("-: "):
            continue
        first = line.split("|")[1]
        for name in re.findall(r"`([A-Z][A-Za-z0-9_]*)`", first):
            rows.setdefault(name, []).append(header + "\n" + _rule(header) + "\n" + line)
    return rows


def _rule(header: str) -> str:
    return "|" + "---|" * (header.count("|") - 1)


def class_page(desc: ClassDescription, example: Example | None, plot: str | None,
               differences: list[str]) -> str:
    lines = [f"## {line[2:-2]}" if line in ("**Parameters**", "**Inputs**", "**Outputs**")
             else line for line in class_section(desc, level=1)]
    lines.insert(2, f"*{category_title(category(desc))}* · `{source_path(desc)}` · "
                    f"`ikaros --class {desc.name}`")
    lines.insert(3, "")
    if differences:
        lines += ["## Ikaros 2, Ikaros 3 and this project", "",
                  "From [the model language's differences](../language.md):", ""]
        for row in differences:
            lines += [row, ""]
    if example is not None:
        lines += ["## Example", ""]
        if example.generated:
            lines += ["No example model uses this class; this one gives each required input "
                      "a constant, with the class at its default parameters:", ""]
        else:
            lines += [f"`{example.path}`"
                      + (f" (run it with `ikaros -b -s 100 {example.path}`)"
                         if example.path.endswith(".ikg") else ""), ""]
        lines += ["```xml", example.text.rstrip(), "```", ""]
        if plot:
            lines += [f"![The outputs of {desc.name} over the example's first "
                      f"{PLOT_TICKS} ticks](images/{plot})", "",
                      f"*The outputs of {desc.name} over the example's first {PLOT_TICKS} "
                      f"ticks: a line per element, or the last tick as an image.*", ""]
    return "\n".join(lines).rstrip() + "\n"


def index_page(classes: dict[str, ClassDescription]) -> str:
    groups: dict[str, list[str]] = {}
    for name, desc in classes.items():
        groups.setdefault(category(desc), []).append(name)
    lines = ["# Classes", "",
             f"The {len(classes)} classes of the standard library, by category, each on a page "
             "of its own made from its class description. `ikaros --classes` lists every "
             "class found, including those beside a model and in installed packages.", ""]
    for cat in sorted(groups, key=category_key):
        lines += [f"## {category_title(cat)}", "", "| Class | What it does |", "|---|---|"]
        for name in groups[cat]:
            first = " ".join(classes[name].description.split()).split(". ")[0]
            lines.append(f"| [{name}]({name}.md) | {first.replace('|', '/')} |")
        lines.append("")
    return "\n".join(lines)


def example_models() -> dict[str, str]:
    """{path relative to the repository: text} of every example model, the modules' own
    first."""
    paths = sorted(glob.glob(os.path.join(EXAMPLES, "modules", "*.ikg"))) + \
        sorted(p for p in glob.glob(os.path.join(EXAMPLES, "**", "*.ikg"), recursive=True)
               if os.sep + "modules" + os.sep not in p)
    models = {}
    for p in paths:
        with open(p, encoding="utf-8") as f:
            models[os.path.relpath(p, ROOT).replace(os.sep, "/")] = f.read()
    return models


def class_pages(images: str) -> dict[str, str]:
    """{page path under classes/: Markdown} of every standard class and the index; the
    plots are written into ``images``."""
    classes = standard_classes()
    models = example_models()
    with open(os.path.join(ROOT, "docs", "language.md"), encoding="utf-8") as f:
        differences = dialect_rows(f.read())
    pages = {"index.md": index_page(classes)}
    for name, desc in classes.items():
        example, plot = example_and_plot(desc, models, images)
        pages[f"{name}.md"] = class_page(desc, example, plot, differences.get(name, []))
    return pages
