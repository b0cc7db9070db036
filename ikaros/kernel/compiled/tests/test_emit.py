"""The emitters' port checks: an element-wise operation runs compiled only when OUTPUT and its
inputs are connected buffers of one size."""
from types import SimpleNamespace

import numpy as np

from ikaros.kernel.compiled import ops
from ikaros.kernel.compiled.emit import EMITTERS, Fragment


def buffer(offset, size):
    return SimpleNamespace(array=np.zeros(size), offset=offset, size=size)


def emit(name, inputs, out_size=3):
    frag = Fragment()
    module = SimpleNamespace(_ik_connected=set(inputs), debug=False)
    loader = EMITTERS[name](frag, module, inputs, {"OUTPUT": buffer(0, out_size)})
    return loader, frag.rows


def test_element_wise_operations_need_inputs_of_the_outputs_size():
    loader, rows = emit("add", {"INPUT1": buffer(10, 3), "INPUT2": buffer(20, 3)})
    assert loader is not None and rows == [(ops.ADD, 0, 3, 10, 20, 0)]
    assert emit("add", {"INPUT1": buffer(10, 3), "INPUT2": buffer(20, 2)}) == (None, [])
    assert emit("add", {"INPUT1": buffer(10, 3)}) == (None, [])
    assert emit("abs", {"INPUT": buffer(10, 3)})[1] == [(ops.ABS, 0, 3, 10, -1, 0)]
    assert emit("abs", {"INPUT": buffer(10, 4)}) == (None, [])
    assert emit("threshold", {"INPUT": SimpleNamespace(array=None, offset=None, size=3)}) \
        == (None, [])
    assert emit("subtract", {"INPUT1": buffer(10, 3)})[1] == [(ops.COPY, 0, 3, 10, -1, 0)]
