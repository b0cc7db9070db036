"""The generated module reference (docs/modules.md) and the descriptions it is made from."""
import difflib
import os
import subprocess
import sys

from ikaros.docgen import COMMAND, module_reference, source_path, standard_classes

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "modules.md")
REGENERATE = f"regenerate it with `{COMMAND}` (or `python -m ikaros --modules-doc`) " \
             f"from the repository root"


def test_docs_modules_md_is_up_to_date():
    expected = module_reference()
    assert os.path.exists(DOC), f"docs/modules.md is missing; {REGENERATE}"
    with open(DOC, encoding="utf-8") as f:
        actual = f.read()
    if actual != expected:
        diff = list(difflib.unified_diff(actual.splitlines(), expected.splitlines(),
                                         "docs/modules.md", "module_reference()",
                                         lineterm="", n=1))
        shown = "\n".join(diff[:40]) + ("\n..." if len(diff) > 40 else "")
        raise AssertionError(f"docs/modules.md is out of date; {REGENERATE}.\n{shown}")


def test_every_standard_class_is_fully_described():
    offenders = []
    for name, desc in standard_classes().items():
        where = source_path(desc)
        if not desc.description.strip():
            offenders.append(f"{name} ({where}): no class description (docstring)")
        for kind, specs in (("parameter", desc.parameters), ("input", desc.inputs),
                            ("output", desc.outputs)):
            for spec in specs:
                if not (spec.description or "").strip():
                    offenders.append(f"{name} ({where}): {kind} {spec.name} has no description")
    assert not offenders, "classes with missing descriptions:\n  " + "\n  ".join(offenders)


def test_reference_lists_only_standard_classes_by_category():
    classes = standard_classes()
    assert classes, "no standard classes found"
    for desc in classes.values():
        assert source_path(desc).startswith("ikaros/modules/"), source_path(desc)
    text = module_reference()
    assert text == module_reference()               # deterministic
    assert "generated" in text.splitlines()[2].lower() and COMMAND in text.splitlines()[2]
    assert "| [Utility](#utility) |" in text
    assert "Source: `ikaros/modules/utility/Scale.py`" in text
    assert text.index("## Utility") < text.index("## IO")


def test_command_prints_or_writes_the_reference(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ikaros", "--modules-doc", "-"],
                       capture_output=True, text=True, timeout=60, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout == module_reference()
    target = tmp_path / "ref.md"
    r = subprocess.run([sys.executable, "-m", "ikaros", "--modules-doc", str(target)],
                       capture_output=True, text=True, timeout=60, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert target.read_text(encoding="utf-8") == module_reference()
    r = subprocess.run([sys.executable, "-m", "ikaros", "--modules-doc",
                        str(tmp_path / "no" / "such" / "dir" / "ref.md")],
                       capture_output=True, text=True, timeout=60, cwd=ROOT)
    assert r.returncode == 1 and "cannot write" in r.stderr
