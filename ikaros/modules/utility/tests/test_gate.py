"""Tests of the Gate module."""

import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load



SIGNAL = ('<module class="Constant" name="C" data="1 -2; 3 4"/>\n'
          '<connection source="C.OUTPUT" target="G.INPUT" delay="0"/>\n')


def test_open_by_default_passes_the_input(tmp_path):
    net = load(tmp_path, SIGNAL + '<module class="Gate" name="G"/>')
    try:
        net.run(ticks=2)
        assert net.output("G.OUTPUT").dtype == np.float32
        assert np.array_equal(net.output("G.OUTPUT"), [[1, -2], [3, 4]])
    finally:
        net.close()


def test_closed_outputs_zero(tmp_path):
    net = load(tmp_path, SIGNAL + '<module class="Gate" name="G" open="no"/>')
    try:
        net.run(ticks=2)
        assert np.array_equal(net.output("G.OUTPUT"), np.zeros((2, 2)))
    finally:
        net.close()


def test_open_from_a_load_override(tmp_path):
    net = load(tmp_path, SIGNAL + '<module class="Gate" name="G"/>', open="no")
    try:
        net.step()
        assert np.array_equal(net.output("G.OUTPUT"), np.zeros((2, 2)))
    finally:
        net.close()


def test_single_element_gate_controls_everything(tmp_path):
    # The gate alternates 1, 0, 1, 0 from tick 0 (Sweep 0..1 step 1); it overrides open="no".
    net = load(tmp_path, SIGNAL +
               '<module class="Sweep" name="W" min="0" max="1" step="1"/>\n'
               '<module class="Gate" name="G" open="no"/>\n'
               '<connection source="W.OUTPUT" target="G.INPUT_GATE" delay="0"/>')
    try:
        for tick in range(4):
            net.step()
            expected = [[1, -2], [3, 4]] if tick % 2 == 0 else np.zeros((2, 2))
            assert np.array_equal(net.output("G.OUTPUT"), expected), tick
    finally:
        net.close()


def test_elementwise_gate(tmp_path):
    net = load(tmp_path, SIGNAL +
               '<module class="Constant" name="K" data="1 0 -1 0.5"/>\n'
               '<module class="Gate" name="G"/>\n'
               '<connection source="K.OUTPUT" target="G.INPUT_GATE" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("G.OUTPUT"), [[1, 0], [0, 4]])
    finally:
        net.close()


def test_gate_of_another_size_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="INPUT_GATE"):
        load(tmp_path, SIGNAL +
             '<module class="Constant" name="K" data="1 0"/>\n'
             '<module class="Gate" name="G"/>\n'
             '<connection source="K.OUTPUT" target="G.INPUT_GATE"/>')
