"""Every conformance model and example, rebuilt through the builder API, saved and loaded,
gives the same network tick by tick as the file loaded directly."""
import glob
import os
import shutil

import numpy as np
import pytest

import ikaros
from ikaros.testing import repeatable_examples
from ikaros.kernel.builder import Builder

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
FILES = sorted(
    [p for p in glob.glob(os.path.join(ROOT, "tests", "conformance", "models", "*.ikg"))
     if not os.path.basename(p).startswith("err_")]
    + repeatable_examples(ROOT))
TICKS = 3


def replicate(source: ikaros.Group, target: ikaros.Group) -> None:
    """Make in ``target``, through the builder API, every element of ``source``."""
    for node in source.node.elements():
        attrs = dict(node.attrs)
        if node.tag == "module":
            module = target.module(attrs.pop("class"), attrs.pop("name", None), **attrs)
            for child in node.elements():
                module.add(child.tag, **child.attrs)
        elif node.tag == "group":
            replicate(source[node.attrs["name"]] if "name" in attrs else
                      ikaros.model.Group._wrap(node, source),
                      target.group(attrs.pop("name", None), **attrs))
        elif node.tag == "connection":
            target.connect(attrs.pop("source", None), attrs.pop("target", None), **attrs)
        elif node.tag == "input":
            target.input(attrs.pop("name"), **attrs)
        elif node.tag == "output":
            target.output(attrs.pop("name"), **attrs)
        elif node.tag == "parameter":
            target.parameter(attrs.pop("name"), **attrs)
        elif node.tag == "view":
            view = target.view(attrs.pop("name", None), **attrs)
            for widget in node.elements():
                view.widget(widget.tag, **widget.attrs)
        elif node.tag == "widget":
            target.widget(**attrs)
        else:
            target.add(node.tag, **attrs)


def outputs(net) -> dict:
    return {f"{inst.path}.{o.name}": net.output(f"{inst.path}.{o.name}")
            for inst in net.schedule for o in inst.module.description.outputs}


@pytest.fixture(scope="module")
def copies(tmp_path_factory):
    """A copy of the examples and conformance models (models may write files)."""
    folder = tmp_path_factory.mktemp("models")
    for part in ("examples", os.path.join("tests", "conformance", "models")):
        shutil.copytree(os.path.join(ROOT, part), folder / part,
                        ignore=shutil.ignore_patterns("output", "__pycache__"))
    return folder


@pytest.mark.parametrize("name", [os.path.relpath(p, ROOT) for p in FILES])
def test_rebuilt_in_code_saved_and_loaded_runs_as_the_file(name, copies, tmp_path):
    path = str(copies / name)
    read = ikaros.Group.read(path)
    attrs = dict(read.attrs)
    model = ikaros.Group(attrs.pop("name", "Main"), **attrs)
    replicate(read, model)
    saved = tmp_path / os.path.basename(path)
    model.save(str(saved))
    # built as if it were the file, so that the files it reads are found
    with open(saved, encoding="utf-8") as f:
        text = f.read()
    with ikaros.load(path, quiet=True) as direct, \
            Builder(path, text=text).build() as again:
        assert again.info() == direct.info()
        for _ in range(TICKS):
            a, b = outputs(direct), outputs(again)
            assert a.keys() == b.keys()
            for key in a:
                assert np.array_equal(a[key], b[key], equal_nan=True), key
            direct.step()
            again.step()
