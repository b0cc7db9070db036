"""pyflakes finds no unused import or variable and no redefinition in our code.

A line marked ``# noqa`` is left alone: an import made only to require an optional package.
"""
from pathlib import Path

from pyflakes import api as pyflakes_api
from pyflakes.reporter import Reporter

ROOT = Path(__file__).resolve().parents[1]


class _Collect(Reporter):
    def __init__(self):
        self.found: list[str] = []

    def unexpectedError(self, filename, message):
        self.found.append(f"{filename}: {message}")

    def syntaxError(self, filename, message, line, column, source):
        self.found.append(f"{filename}:{line}: {message}")

    def flake(self, message):
        line = Path(message.filename).read_text().splitlines()[message.lineno - 1]
        if "# noqa" not in line:
            self.found.append(str(message))


def test_pyflakes_is_clean():
    reporter = _Collect()
    pyflakes_api.checkRecursive([str(ROOT / part) for part in ("ikaros", "tests", "benchmarks")],
                                reporter)
    assert reporter.found == []
