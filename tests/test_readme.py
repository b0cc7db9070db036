"""What the README shows is true (issue 37, item 8: its ``ikaros.load`` snippet left out the
``Show: 0.375`` line that Show prints before the documented output)."""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def test_the_load_snippet_prints_what_the_readme_shows():
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        text = f.read()
    m = re.search(r"```python\n(import ikaros\nnet = ikaros\.load\(.*?)```.*?```text\n(.*?)```",
                  text, re.S)
    assert m, "the README's ikaros.load snippet and its output"
    code, shown = m.groups()
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=60, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert out.stdout == shown


def test_the_test_command_leaves_the_demos_environment_alone():
    """Issue 37, item 9: the README's test command installed the package, editable and with
    every extra, into the .venv its demo step made, so a server running from it lost its
    static files. The tests get an environment of their own, which git ignores."""
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    demo = re.search(r"python3 -m venv (\S+) && \. \1/bin/activate && pip install '\.\[web\]'",
                     readme)
    assert demo, "the README's demo step"
    assert "bash scripts/test.sh" in readme
    with open(os.path.join(ROOT, "scripts", "test.sh"), encoding="utf-8") as f:
        script = f.read()
    made = re.findall(r"python3 -m venv (\S+)", script)
    assert len(made) == 1 and made[0] != demo.group(1), made
    assert f". {made[0]}/bin/activate" in script
    with open(os.path.join(ROOT, ".gitignore"), encoding="utf-8") as f:
        assert f"{made[0]}/" in f.read().split()
    with open(os.path.join(ROOT, ".ci", "run"), encoding="utf-8") as f:
        assert "bash scripts/test.sh" in f.read()
