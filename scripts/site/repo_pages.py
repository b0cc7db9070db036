"""Pages of the documentation site made from files outside ``docs/``: getting started (the
README's quick start), contributing (CONTRIBUTING.md) and the benchmarks
(benchmarks/README.md) with plots of their figures beside the tables."""
from __future__ import annotations

import os
import re

from plots import bar_chart

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# the README's sections that make the getting-started page, in order
GETTING_STARTED = ("Install and run the demo", "Examples", "A model in ten lines",
                   "The same model in Python", "A module in ten lines", "Run the tests")


def _read(*parts: str) -> str:
    with open(os.path.join(ROOT, *parts), encoding="utf-8") as f:
        return f.read()


def site_links(text: str, base: str) -> str:
    """Markdown links of a file in folder ``base`` (relative to the repository) as links
    between the site's pages: docs/x.md is x.md, the README getting-started.md,
    CONTRIBUTING.md contributing.md, benchmarks/README.md benchmarks.md; a link to any other
    file of the repository becomes its path as code."""
    pages = {"README.md": "getting-started.md", "CONTRIBUTING.md": "contributing.md",
             "benchmarks/README.md": "benchmarks.md", "docs/modules.md": "classes/index.md"}

    def page(match: re.Match) -> str:
        bang, label, target = match.group(1), match.group(2), match.group(3)
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            return match.group(0)
        path, _, anchor = target.partition("#")
        full = os.path.normpath(os.path.join(base, path)).replace(os.sep, "/")
        if full in pages:
            new = pages[full]
        elif full.startswith("docs/"):
            new = full[len("docs/"):]
        else:
            return f"{label} (`{full}`)"
        return f"{bang}[{label}]({new}{'#' + anchor if anchor else ''})"
    return re.sub(r"(!?)\[([^\]]*)\]\(([^)\s]+)\)", page, text)


def sections(markdown: str) -> dict[str, str]:
    """{title: text} of the level-2 sections of a Markdown text."""
    parts = re.split(r"^## (.+)$", markdown, flags=re.M)
    return {parts[i].strip(): parts[i + 1] for i in range(1, len(parts), 2)}


def getting_started() -> str:
    found = sections(_read("README.md"))
    missing = [t for t in GETTING_STARTED if t not in found]
    if missing:
        raise ValueError(f"README.md has no section {missing[0]!r} for getting-started.md")
    body = "".join(f"## {t}\n{found[t]}" for t in GETTING_STARTED)
    return "# Getting started\n\n" + site_links(body, "")


def contributing() -> str:
    return site_links(_read("CONTRIBUTING.md"), "")


def _number(cell: str) -> float | None:
    """The upper end of a figure such as "4.0–4.1", "≈ 80", "0.19 s" (None: no single
    figure)."""
    cell = cell.replace(",", "").replace("≈", "").strip()
    m = re.fullmatch(r"(-?[\d.]+)(?:\s*[–-]\s*(-?[\d.]+))?\s*[a-zµ]*", cell)
    if not m:
        return None
    return float(m.group(2) or m.group(1))


def _tables(markdown: str):
    """(start line, end line, header cells, rows of cells) of every Markdown table."""
    lines = markdown.split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("|") and k + 1 < len(lines) and \
                re.fullmatch(r"\|(\s*:?-+:?\s*\|)+", lines[k + 1].strip()):
            start = k
            header = [c.strip() for c in lines[k].strip().strip("|").split("|")]
            k += 2
            rows = []
            while k < len(lines) and lines[k].startswith("|"):
                rows.append([c.strip() for c in lines[k].strip().strip("|").split("|")])
                k += 1
            yield start, k, header, rows
        else:
            k += 1


def _speedup_chart(header, rows, path: str) -> bool:
    """A bar per row that has both figures: how many times the C++ figure the Python one
    is (the slowest run of each range)."""
    cpp, ours = header.index("C++ Ikaros 3"), header.index("ikaros for Python")
    labels, values = [], []
    for row in rows:
        a, b = _number(row[cpp]), _number(row[ours])
        if a and b and a > 0 and b > 0:
            labels.append(row[0].split(",")[0] if len(row[0]) > 40 else row[0])
            values.append(round(a / b, 1))
    if not labels:
        return False
    bar_chart(path, "How many times faster than C++ Ikaros 3 (same machine class)", labels,
              {"C++ figure / ikaros for Python's": values}, "times faster (log scale)")
    return True


def _simulator_charts(header, rows, folder: str, stem: str) -> list[str]:
    """Grouped bars of the run's CPU time and the peak memory, per network and simulator."""
    made = []
    networks = list(dict.fromkeys(r[0] for r in rows))
    simulators = list(dict.fromkeys(r[1] for r in rows))
    for column, unit in (("run CPU s", "CPU seconds for 1 s of model time (log scale)"),
                         ("peak MB", "peak memory, MB (log scale)")):
        if column not in header:
            continue
        c = header.index(column)
        series = {s: [next((_number(r[c]) for r in rows if r[0] == n and r[1] == s), None)
                      for n in networks] for s in simulators}
        name = f"{stem}-{'cpu' if 'CPU' in column else 'memory'}.svg"
        bar_chart(os.path.join(folder, name), column, networks, series, unit)
        made.append(name)
    return made


def benchmarks(images: str) -> str:
    """benchmarks/README.md with a plot after each table of figures it can draw."""
    text = site_links(_read("benchmarks", "README.md"), "benchmarks")
    lines = text.split("\n")
    inserts: dict[int, list[str]] = {}
    for n, (_, end, header, rows) in enumerate(_tables(text)):
        made = []
        if "C++ Ikaros 3" in header and "ikaros for Python" in header:
            name = f"bench-{n}-speedup.svg"
            if _speedup_chart(header, rows, os.path.join(images, name)):
                made.append(name)
        elif header[:2] == ["network", "simulator"]:
            made = _simulator_charts(header, rows, images, f"bench-{n}")
        if made:
            inserts[end] = [""] + [f"![A plot of the table above](images/{m})" for m in made]
    out = []
    for k, line in enumerate(lines):
        out.extend(inserts.get(k, []))
        out.append(line)
    return "\n".join(out)
