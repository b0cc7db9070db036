"""net.save() writes a model that loads again and gives the same outputs, for every model
of the suite."""
import glob
import os
import shutil

import numpy as np
import pytest

import ikaros
from conformance_util import MODELS

GOOD = sorted(os.path.basename(p) for p in glob.glob(os.path.join(MODELS, "*.ikg"))
              if not os.path.basename(p).startswith("err_"))


def _outputs(net):
    out = {}
    for inst in net.schedule:
        for name in inst.module.description.outputs:
            out[f"{inst.path}.{name.name}"] = net.output(f"{inst.path}.{name.name}")
    return out


@pytest.mark.parametrize("name", GOOD)
def test_save_round_trip(name, tmp_path):
    original = ikaros.load(os.path.join(MODELS, name))
    # the saved file needs the model's classes and group files beside it
    for helper in glob.glob(os.path.join(MODELS, "*")):
        if os.path.basename(helper) != name and not os.path.basename(helper).startswith("err_") \
                and os.path.isfile(helper):
            shutil.copy(helper, tmp_path)
    saved = tmp_path / name
    original.save(str(saved))
    again = ikaros.load(str(saved))
    a, b = _outputs(original), _outputs(again)
    assert a.keys() == b.keys()
    for _ in range(4):
        for path in a:
            assert np.array_equal(original.output(path), again.output(path)), path
        original.step()
        again.step()
    assert _listing(original) == _listing(again)


def _listing(net) -> str:
    """The connections, schedule and memory of ``net.info()``; not its last line, which says
    whether the compiled tick, made in the background, is there yet."""
    return net.info().split("Connections:")[1].rsplit("\nCompiled tick:", 1)[0]
