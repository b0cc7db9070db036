"""Every case of every golden file: the original C++ Ikaros 3's outputs on small models.

The golden files are copies of the project's ``shared/golden/*.json`` in
``tests/golden/files`` (so that the tests run in any clone), read as they are; where
``shared/`` lies beside the repository (``IKAROS_SHARED`` names another folder) the copies
must equal it. Each case's model is run for its
ticks, and after the k-th tick every output the file records for tick k is compared, shape
and values (numpy ``allclose``, rtol = atol = 1e-5, NaN equal to ``null``), as the golden
README says. The models are Ikaros 3 files, so they are loaded with ``dialect=3``: most of
them use no Ikaros 3-only form that would make the loader see it by itself.
"""
import glob
import json
import math
import os

import numpy as np
import pytest

import ikaros

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHARED = os.environ.get("IKAROS_SHARED") or os.path.join(os.path.dirname(ROOT), "shared")
GOLDEN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "files")

RTOL = ATOL = 1e-5
# golden/README.md: classes that integrate at sub-tick steps may need rtol 1e-4
LOOSER = {"IntegrateAndFirePopulation": 1e-4, "RatePopulation": 1e-4, "KalmanFilter": 1e-4}


def _cases() -> list:
    cases = []
    for file in sorted(glob.glob(os.path.join(GOLDEN, "*.json"))):
        with open(file, encoding="utf-8") as f:
            golden = json.load(f)
        for case in golden["cases"]:
            cases.append(pytest.param(golden["class"], case,
                                      id=f'{golden["class"]}-{case["name"]}'))
    return cases


def _expected(value) -> np.ndarray:
    """A recorded value as an array: ``null`` (NaN or an infinity in C++) is NaN."""
    def numbers(v):
        return [numbers(x) for x in v] if isinstance(v, list) else \
            (math.nan if v is None else v)
    return np.asarray(numbers(value), dtype=np.float64)


def _agrees(got: np.ndarray, want: np.ndarray, rtol: float) -> bool:
    """Within the tolerance; where C++ wrote ``null`` (NaN or an infinity: the files do
    not tell which) any value that is not finite agrees."""
    unknown = np.isnan(want)
    return bool(np.all(~np.isfinite(got[unknown]))) and \
        np.allclose(got[~unknown], want[~unknown], rtol=rtol, atol=ATOL)


@pytest.mark.parametrize("cls, case", _cases())
def test_golden_case(cls, case, tmp_path):
    rtol = LOOSER.get(cls, RTOL)
    path = tmp_path / "golden.ikg"
    path.write_text(case["model"], encoding="utf-8")
    differences = []
    with ikaros.load(str(path), quiet=True, dialect=3) as net:
        for k in range(1, case["ticks"] + 1):
            net.step()
            for output, value in case["outputs"][str(k)].items():
                want = _expected(value)
                got = np.asarray(net.output(output), dtype=np.float64)
                if got.shape != want.shape:
                    differences.append(f"tick {k} {output}: shape {list(got.shape)}, "
                                       f"C++ {list(want.shape)}")
                elif not _agrees(got, want, rtol):
                    differences.append(f"tick {k} {output}: {got.tolist()}, "
                                       f"C++ {want.tolist()}")
    assert not differences, f"{len(differences)} differences; the first: " + \
        "; ".join(differences[:3])


@pytest.mark.skipif(not os.path.isdir(os.path.join(SHARED, "golden")),
                    reason="the project's shared/ folder is not beside this clone")
def test_the_copies_are_the_shared_golden_files():
    shared = os.path.join(SHARED, "golden")
    names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(shared, "*.json")))
    assert names == sorted(os.path.basename(p) for p in glob.glob(os.path.join(GOLDEN, "*.json")))
    for name in names:
        with open(os.path.join(shared, name), "rb") as a, open(os.path.join(GOLDEN, name),
                                                              "rb") as b:
            assert a.read() == b.read(), f"tests/golden/files/{name} differs from shared/"
