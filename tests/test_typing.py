"""The public API is typed (PEP 561: ikaros/py.typed): mypy passes on it (the files named in
pyproject.toml's [tool.mypy]) and on the README's examples, and it finds the mistakes a user
module or script makes with it."""
import os
import re
import subprocess
import sys

import pytest

pytest.importorskip("mypy")
pytestmark = pytest.mark.slow

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _mypy(*args: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, MYPYPATH=ROOT)
    return subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", *args], cwd=ROOT,
                          env=env, capture_output=True, text=True, timeout=600)


def _readme_code(title: str) -> str:
    """The Python code block of the README's section ``title``."""
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        text = f.read()
    section = text.split(f"## {title}\n", 1)[1].split("\n## ", 1)[0]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def test_the_public_api_passes_the_type_checker():
    done = _mypy()
    assert done.returncode == 0, done.stdout[-3000:]
    assert os.path.exists(os.path.join(ROOT, "ikaros", "py.typed"))


WRONG = '''
from ikaros import Module, Parameter, Input, Output
import ikaros


class Wrong(Module):
    rate = Parameter(0.1, "a rate")
    INPUT = Input("the signal")
    OUTPUT = Output("the result", shape="INPUT.shape")

    def tick(self):
        self.OUTPUT = "no array"
        self.INPUT.no_such_method()


net = ikaros.load("model.ikg")
net.run(ticks="ten")
'''


@pytest.fixture(scope="module")
def checked(tmp_path_factory):
    """mypy's output on the README's examples and on a user's module with mistakes (one run
    for both: mypy reads the package once)."""
    folder = tmp_path_factory.mktemp("typing")
    files = {"Leaky.py": _readme_code("A module in ten lines"),
             "load_example.py": _readme_code("A model in ten lines"),
             "group_example.py": _readme_code("The same model in Python"),
             "Wrong.py": WRONG}
    for name, code in files.items():
        (folder / name).write_text(code)
    done = _mypy("--follow-imports=silent", "--ignore-missing-imports", "--check-untyped-defs",
                 "--cache-dir", str(folder / "cache"), *(str(folder / n) for n in files))
    assert "Wrong.py" in done.stdout, done.stdout[-3000:] + done.stderr[-3000:]
    return done.stdout


def test_the_readmes_examples_pass_the_type_checker(checked):
    errors = [line for line in checked.splitlines() if ": error:" in line
              and "Wrong.py" not in line]
    assert not errors, checked[-3000:]


def test_the_checker_finds_a_users_mistakes(checked):
    out = checked
    assert re.search(r'Wrong.py:12: error: Incompatible types in assignment .*"str"', out), out
    assert re.search(r'Wrong.py:13: error: .*has no attribute "no_such_method"', out), out
    assert re.search(r'Wrong.py:17: error: Argument "ticks" to "run" of "Network" has '
                     r'incompatible type "str"', out), out
