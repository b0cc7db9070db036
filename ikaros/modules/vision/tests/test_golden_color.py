"""ColorTransform, WhiteBalance and ColorMatch against the outputs of the original C++
Ikaros 3 (the golden files, copied unchanged into the folder golden/ here): every
case, every recorded tick, compared as the golden README says (C++ record "k" against the
network after k steps; numpy allclose with rtol = atol = 1e-5). All cases feed the module
with delay-0 connections, so the tick conventions of the two programs agree."""
import json
import os

import numpy as np
import pytest

import ikaros
from ikaros.module import Module

CLASSES = ("ColorTransform", "WhiteBalance", "ColorMatch")
FOLDER = os.path.join(os.path.dirname(__file__), "golden")


def cases() -> list:
    found = []
    for cls in CLASSES:
        with open(os.path.join(FOLDER, f"{cls}.json"), encoding="utf-8") as f:
            found += [pytest.param(cls, case, id=f"{cls}-{case['name']}")
                      for case in json.load(f)["cases"]]
    return found


@pytest.fixture
def ikaros3(monkeypatch):
    """The golden models are Ikaros 3 files: their modules see dialect "3" whatever the
    kernel reads from the file."""
    monkeypatch.setattr(Module, "dialect", property(lambda self: "3", lambda self, v: None))


@pytest.mark.parametrize("cls, case", cases())
def test_golden_case(tmp_path, ikaros3, cls, case):
    path = tmp_path / "model.ikg"
    path.write_text(case["model"], encoding="utf-8")
    with ikaros.load(str(path)) as net:
        for tick in range(1, case["ticks"] + 1):
            net.step()
            for output, expected in case["outputs"][str(tick)].items():
                expected = np.array(expected, dtype=float)
                actual = net.output(output)
                assert actual.shape == expected.shape, (tick, output)
                assert np.allclose(actual, expected, rtol=1e-5, atol=1e-5), \
                    (tick, output, actual.tolist(), expected.tolist())
