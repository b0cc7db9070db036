"""Tests of the Add module."""

import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load



def test_adds_1d(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2 3"/>\n'
               '<module class="Constant" name="B" data="10 20 -30.5"/>\n'
               '<module class="Add" name="S"/>\n'
               '<connection source="A.OUTPUT" target="S.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="S.INPUT2" delay="0"/>')
    try:
        net.run(ticks=2)
        out = net.output("S.OUTPUT")
        assert out.dtype == np.float32
        assert np.array_equal(out, np.array([11, 22, -27.5], np.float32))
    finally:
        net.close()


def test_adds_2d(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2; 3 4"/>\n'
               '<module class="Constant" name="B" data="0.5 0.5; -1 -1"/>\n'
               '<module class="Add" name="S"/>\n'
               '<connection source="A.OUTPUT" target="S.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="S.INPUT2" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), [[1.5, 2.5], [2, 3]])
    finally:
        net.close()


def test_follows_a_changing_input_tick_by_tick(tmp_path):
    # Sweep writes 0 in init and k+1 on tick k; with delay 1 Add sees k on tick k.
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="0" max="100" step="1" outputsize="2"/>\n'
               '<module class="Constant" name="C" data="100 200"/>\n'
               '<module class="Add" name="Now"/>\n'
               '<module class="Add" name="Late"/>\n'
               '<connection source="W.OUTPUT" target="Now.INPUT1" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="Now.INPUT2" delay="0"/>\n'
               '<connection source="W.OUTPUT" target="Late.INPUT1" delay="1"/>\n'
               '<connection source="C.OUTPUT" target="Late.INPUT2"/>')
    try:
        for tick in range(5):
            net.step()
            assert np.array_equal(net.output("Now.OUTPUT"), [tick + 101, tick + 201])
            assert np.array_equal(net.output("Late.OUTPUT"), [tick + 100, tick + 200])
    finally:
        net.close()


def test_inputs_of_different_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same size"):
        load(tmp_path,
             '<module class="Constant" name="A" data="1 2 3"/>\n'
             '<module class="Constant" name="B" data="1 2"/>\n'
             '<module class="Add" name="S"/>\n'
             '<connection source="A.OUTPUT" target="S.INPUT1"/>\n'
             '<connection source="B.OUTPUT" target="S.INPUT2"/>')
