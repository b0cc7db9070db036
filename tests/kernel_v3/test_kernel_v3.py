"""The Ikaros 3 kernel tests, re-written as our own models (reference TESTS.md §2).

Every ``models/<section>/test_*.ikg`` (sections as in the catalogue: parameters,
expressions, ..., modules) is run through the CLI in batch mode, in this process, and its
expectations are read from root attributes, as the original harness does (TESTS.md §2.1):

* ``stop`` runs that many ticks; without it ``-s 0`` is added (build and init only);
* ``cli_args`` are put before the file (whitespace-separated);
* ``expected_exit`` (default 0);
* ``expected_output_contains`` / ``_not_contains`` / ``_once`` / ``_twice``: ``||``-separated
  texts matched against stdout plus stderr; ``expected_output_in_order``: texts that
  appear in this order (ours);
* ``expected_file_exists`` / ``_not_exists`` / ``expected_file_contains`` /
  ``_not_contains`` (``path::text``; a file that cannot be read contains nothing);
* ``initial_file`` is written with ``initial_file_contents`` before the run.

``${TEST_DIR}`` is the model's folder, ``${TMP}`` a fresh temporary folder and
``${PYTHON}`` the interpreter running the tests (for ``--python``). A model that
reads what another writes (a state file) names it in ``requires``: that model runs first,
with the same ``${TMP}``, and must pass too. ``run_in_tmp="true"`` runs a copy of the model
placed in ``${TMP}`` (for a model that writes beside itself). Where our
documented semantics differ from Ikaros 3 (first tick 0, concatenation, ...), the models
expect our result; docs/language.md lists the differences.

A model with an ``http_requests`` script is run as an ``ikaros`` process serving the web UI
instead (http_harness.py), with the same pass criteria.

The test-only classes the models use live in ikaros/testsupport; the models reach them with
``path="@support"`` on the module and ``support`` on the top group.
"""
import os
import shlex
import shutil
import sys

import http_harness
import pytest

import ikaros
from ikaros import cli
from ikaros.kernel.classes import ClassRegistry
from ikaros.language.reader import read_file

MODELS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "models")

def _models():
    """section/file of every test model."""
    return sorted(f"{section}/{f}" for section in os.listdir(MODELS)
                  if os.path.isdir(os.path.join(MODELS, section))
                  for f in os.listdir(os.path.join(MODELS, section))
                  if f.startswith("test") and f.endswith(".ikg"))


def _texts(attrs, key):
    value = attrs.get(key)
    return [t.strip() for t in value.split("||")] if value else []


def _run_batch(path: str, attrs, cli_args: list[str], capsys) -> tuple[int, str]:
    """Runs the model in batch mode in this process: (exit status, output)."""
    argv = ["-b"] + cli_args
    if "stop" not in attrs:
        argv += ["-s", "0"]
    try:
        code = cli.main(argv + [path])
    except SystemExit as e:             # a usage error (exit status 2)
        code = e.code
    out = capsys.readouterr()
    return code, out.out + out.err


def _run(name: str, tmp_path, capsys) -> list[str]:
    """Runs one model through the CLI; returns its unmet expectations (none: it passes)."""
    path = os.path.join(MODELS, name)
    attrs = read_file(path, root_tag="group").attrs
    for required in _texts(attrs, "requires"):
        unmet = _run(os.path.join(os.path.dirname(name), required), tmp_path, capsys)
        if unmet:
            return [f"the required {required} failed:"] + unmet
    if attrs.get("run_in_tmp") == "true":
        path = shutil.copy(path, tmp_path)

    def expand(text):
        return text.replace("${TEST_DIR}", os.path.dirname(path)).replace(
            "${TMP}", str(tmp_path)).replace("${PYTHON}", sys.executable)

    if attrs.get("initial_file"):
        with open(expand(attrs["initial_file"]), "w", encoding="utf-8") as f:
            f.write(expand(attrs.get("initial_file_contents", "")))
    cli_args = shlex.split(attrs.get("cli_args", ""))
    if "http_requests" in attrs or "http_occupy_port" in attrs:
        code, output, unmet = http_harness.run(path, attrs, cli_args, expand, tmp_path)
    else:
        unmet = []
        code, output = _run_batch(path, attrs, [expand(a) for a in cli_args], capsys)
    if code != int(attrs.get("expected_exit", "0")):
        unmet.append(f"exit status {code}")
    for text in _texts(attrs, "expected_output_contains"):
        if expand(text) not in output:
            unmet.append(f"{text!r} not in the output")
    for text in _texts(attrs, "expected_output_not_contains"):
        if expand(text) in output:
            unmet.append(f"{text!r} in the output")
    for key, count in (("expected_output_contains_once", 1),
                       ("expected_output_contains_twice", 2)):
        for text in _texts(attrs, key):
            if output.count(expand(text)) != count:
                unmet.append(f"{text!r} not {count} times in the output")
    at = 0
    for text in _texts(attrs, "expected_output_in_order"):
        at = output.find(expand(text), at)
        if at < 0:
            unmet.append(f"{text!r} not in the output after the texts before it")
            break
    for file in _texts(attrs, "expected_file_exists"):
        if not os.path.exists(expand(file)):
            unmet.append(f"no file {file}")
    for file in _texts(attrs, "expected_file_not_exists"):
        if os.path.exists(expand(file)):
            unmet.append(f"a file {file}")
    for key, wanted in (("expected_file_contains", True),
                        ("expected_file_not_contains", False)):
        for item in _texts(attrs, key):
            file, _, text = item.partition("::")
            try:
                with open(expand(file), encoding="utf-8") as f:
                    found = expand(text) in f.read()
            except OSError:
                found = False
            if found != wanted:
                unmet.append(f"{text!r} {'not ' if wanted else ''}in {file}")
    return unmet + ([f"output:\n{output}"] if unmet else [])


@pytest.mark.parametrize("name", _models())
def test_kernel_model(name, tmp_path, capsys):
    unmet = _run(name, tmp_path, capsys)
    assert not unmet, "\n".join(unmet)


def test_support_classes_are_found_but_internal():
    """The test-only classes are found in their folder but listed nowhere."""
    support = os.path.join(os.path.dirname(ikaros.__file__), "testsupport")
    registry = ClassRegistry([support])
    names = ["KernelTestModule", "DelaySequenceSource", "TaskLifecycleTestModule",
             "PersistentStateTestModule", "MatrixFunctionTestModule",
             "ComputeEngineTestModule"]
    for name in names:
        assert registry.find(name).description().internal, name
    listed = ikaros.classes(support)
    assert not set(names) & set(listed) and "Constant" in listed
