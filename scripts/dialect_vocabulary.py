"""Write ikaros/language/vocabulary.py: the class names, parameter names and option labels
that only one version of the original Ikaros uses, from the reference's catalogues.

    python scripts/dialect_vocabulary.py ../shared

reads ``reference/IKAROS3-INTERFACES.md`` (Ikaros 3's classes today, with the test-only classes
of its kernel tests, TESTS.md §2.1), ``reference/MODULES.md``
(Ikaros 2's catalogue) and ``golden-v2/*.json`` (classes the Ikaros 2 program of 2024 runs,
which the catalogue of 2020 lacks in part). Only names are taken: they are facts about which
version has what. A parameter counts as Ikaros 3's alone only where the catalogue lists the
class's Ikaros 2 parameters in full (some entries end in "… (+n)" or list none).
"""
import glob
import json
import os
import re
import sys
from xml.etree import ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "ikaros", "language", "vocabulary.py")


# the test-only classes of Ikaros 3's kernel tests (reference TESTS.md §2.1, DynamicMatrix*
# as this project names them)
TEST_CLASSES = {
    "KernelTestModule", "KernelSizeTestModule", "KernelSizedInputTestModule",
    "DelaySequenceSource", "DelayVectorSource", "DelayWindowSink", "DelayFlatWindowSink",
    "DelayStackedWindowSink", "FirstTickReporter", "StartupStepReporter",
    "TaskLifecycleTestModule", "PersistentStateTestModule", "AsyncLifecycleTestModule",
    "DynamicMatrixSource", "DynamicMatrixSink", "DynamicMatrixCopy",
    "MatrixFunctionTestModule", "ComputeEngineTestModule"}


def ikaros3(text: str) -> tuple[dict, dict]:
    """{class: {parameter: [options]}} and {class: {port}} of IKAROS3-INTERFACES.md."""
    classes, ports = {}, {}
    for block in re.split(r"\n## ", text)[1:]:
        name = block.split("\n", 1)[0].strip()
        ports[name] = set()
        for kind in ("Inputs", "Outputs"):
            line = re.search(rf"- {kind}: (.*)", block)
            if line and line.group(1).strip() != "—":
                ports[name] |= {p.strip("`").split(" ")[0] for p in line.group(1).split("; ")}
        params = {}
        line = re.search(r"- Parameters: (.*)", block)
        if line and line.group(1).strip() != "—":
            for item in line.group(1).split("`; `"):
                item = item.strip("`")
                m = re.match(r"(\S+) \((.*)\)$", item)
                if not m:
                    continue
                options = re.search(r"options=(.*?)(?:, \w+=|$)", m.group(2))
                params[m.group(1)] = [o.strip() for o in options.group(1).split(",")] \
                    if options else []
        classes[name] = params
    return classes, ports


def ikaros2_ports(text: str) -> dict:
    """{class: {port}} of the catalogue, for classes whose ports it names all (no ``*``)."""
    ports = {}
    for block in re.split(r"\n### ", text)[1:]:
        name = block.split("\n", 1)[0].strip()
        found = set()
        for kind in ("Inputs", "Outputs"):
            line = re.search(rf"\* {kind}: (.*)", block)
            listed = line.group(1).strip() if line else "—"
            found |= set(re.findall(r"`([A-Za-z_][\w\-]*)", listed))
        if "*" not in found:
            ports[name] = found
    return ports


def _ikaros2_uses(model: str, v2: dict, v2_ports: dict) -> None:
    """Add the ports and parameters an Ikaros 2 model that the Ikaros 2 program ran uses (the
    catalogue is of 2020 and names the key parameters only)."""
    root = ElementTree.fromstring(model)
    classes = {m.get("name"): m.get("class") for m in root.iter("module")}
    for module in root.iter("module"):
        params, _ = v2.setdefault(module.get("class"), ({}, False))
        for key, value in module.attrib.items():
            params.setdefault(key, [])
            if params[key] and value not in params[key]:
                params[key].append(value)
    for connection in root.iter("connection"):
        for end in (connection.get("source"), connection.get("target")):
            name, _, port = end.rpartition(".")
            if classes.get(name) in v2_ports:
                v2_ports[classes[name]].add(port)


def ikaros2(text: str) -> dict:
    """{class: ({parameter: [options]}, whether the catalogue lists them all)}."""
    classes = {}
    for block in re.split(r"\n### ", text)[1:]:
        name = block.split("\n", 1)[0].strip()
        line = re.search(r"\* Parameters: (.*)", block)
        listed = line.group(1).strip() if line else "—"
        params = {}
        for m in re.finditer(r"(\w+)(?:∈\{([^}]*)\})?(?:=[^,]*)?(?:, |$)", listed):
            params[m.group(1)] = m.group(2).split(",") if m.group(2) else []
        classes[name] = (params, listed != "—" and "(+" not in listed)
    return classes


def main(shared: str) -> None:
    with open(os.path.join(shared, "reference", "IKAROS3-INTERFACES.md"), encoding="utf-8") as f:
        v3, v3_ports = ikaros3(f.read())
    with open(os.path.join(shared, "reference", "MODULES.md"), encoding="utf-8") as f:
        catalogue = f.read()
    v2, v2_ports = ikaros2(catalogue), ikaros2_ports(catalogue)
    golden = set()
    for file in glob.glob(os.path.join(shared, "golden-v2", "*.json")):
        with open(file, encoding="utf-8") as f:
            recorded = json.load(f)
        golden.add(recorded["class"])
        for case in recorded["cases"]:
            _ikaros2_uses(case["model"], v2, v2_ports)
    with open(os.path.join(shared, "golden-v2", "README.md"), encoding="utf-8") as f:
        readme = f.read()
    # classes the golden README names as Ikaros 2's but could not record
    named = {n for n in re.findall(r"`([A-Z][A-Za-z0-9_]+)`", readme) if not n.isupper()}
    in_v2 = set(v2) | golden | (named - set(v3))
    only3 = sorted((set(v3) | TEST_CLASSES) - in_v2)
    only2 = sorted(in_v2 - set(v3))
    params, labels, ports3, ports2 = {}, {}, {}, {}
    for cls in sorted(set(v3) & set(v2_ports)):
        if v3_ports[cls] - v2_ports[cls]:
            ports3[cls] = sorted(v3_ports[cls] - v2_ports[cls])
        if v2_ports[cls] - v3_ports[cls]:
            ports2[cls] = sorted(v2_ports[cls] - v3_ports[cls])
    for cls in sorted(set(v3) & set(v2)):
        known, complete = v2[cls]
        new = sorted(p for p in v3[cls] if p not in known)
        if new and complete:
            params[cls] = new
        for p, options in v3[cls].items():
            if p in known and known[p] and options:
                extra = sorted(set(options) - set(known[p]))
                if extra:
                    labels[f"{cls}.{p}"] = extra
    lines = ['"""The names only one version of the original Ikaros uses: signs of which version a',
             "model file was written for (ikaros/language/dialect.py). Made by",
             "scripts/dialect_vocabulary.py from the reference's catalogues; do not edit by hand.",
             '"""', "",
             "# classes that only Ikaros 3 has (with the test-only classes of its kernel tests)",
             f"IKAROS3_CLASSES = frozenset({_names(only3)})", "",
             "# classes that only Ikaros 2 has",
             f"IKAROS2_CLASSES = frozenset({_names(only2)})", "",
             "# parameters that only Ikaros 3's class of that name has",
             "IKAROS3_PARAMETERS = {"]
    lines += [f'    "{c}": frozenset({_names(p, 8)}),' for c, p in params.items()]
    lines += ["}", "", "# option labels that only Ikaros 3's parameter of that name has",
              "IKAROS3_LABELS = {"]
    lines += [f'    "{k}": frozenset({_names(v, 8)}),' for k, v in labels.items()]
    lines += ["}", "", "# inputs and outputs that only Ikaros 3's class of that name has",
              "IKAROS3_PORTS = {"]
    lines += [f'    "{c}": frozenset({_names(p, 8)}),' for c, p in ports3.items()]
    lines += ["}", "", "# inputs and outputs that only Ikaros 2's class of that name has",
              "IKAROS2_PORTS = {"]
    lines += [f'    "{c}": frozenset({_names(p, 8)}),' for c, p in ports2.items()]
    lines += ["}", ""]
    with open(OUT, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


def _names(names: list, indent: int = 4) -> str:
    """A set literal wrapped at 96 columns."""
    out, line = [], ""
    for n in names:
        item = f'"{n}", '
        if len(line) + len(item) > 92 - indent:
            out.append(line.rstrip())
            line = ""
        line += item
    out.append(line.rstrip().rstrip(","))
    pad = "\n" + " " * indent
    return "{" + pad + pad.join(out) + "\n" + " " * (indent - 4) + "}"


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "shared"))
