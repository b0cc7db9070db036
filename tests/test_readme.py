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
