"""The shared memory of a scripted module's inputs and outputs."""
import os

import numpy as np

from ikaros.scripted.shared import SharedArrays


def test_both_sides_see_the_same_memory_and_no_file_is_left():
    mine = SharedArrays.create({"in:A": (2, 3), "out:B": (5,), "out:C": (), "in:D": (0,)})
    assert os.path.exists(mine.path)
    theirs = SharedArrays.open(mine.description)
    assert not os.path.exists(mine.path)          # the worker removed the name
    assert {k: a.shape for k, a in theirs.arrays.items()} == \
        {"in:A": (2, 3), "out:B": (5,), "out:C": (), "in:D": (0,)}
    assert all(a.dtype == np.float32 and not a.any() for a in theirs.arrays.values())
    mine.arrays["in:A"][...] = np.arange(6).reshape(2, 3)
    theirs.arrays["out:B"][...] = [1, 2, 3, 4, 5]
    theirs.arrays["out:C"][...] = 7
    assert theirs.arrays["in:A"].tolist() == [[0, 1, 2], [3, 4, 5]]
    assert mine.arrays["out:B"].tolist() == [1, 2, 3, 4, 5] and mine.arrays["out:C"] == 7
    offsets = sorted(o for o, _ in mine.description["layout"].values())
    assert all(o % 64 == 0 for o in offsets)


def test_no_arrays_still_make_a_mapping():
    shared = SharedArrays.create({})
    assert shared.arrays == {} and shared.description["size"] == 64
    os.unlink(shared.path)
