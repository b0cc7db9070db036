"""Tests of the InitialValue module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_holds_data_for_wait_ticks_then_accumulates(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="Flow" data="1 -2"/>'
               '<module class="InitialValue" name="S" data="10 20" wait="2"/>'
               '<connection source="Flow.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        assert np.array_equal(net.output("S.OUTPUT"), [10, 20])     # size from data; init
        got = []
        for _ in range(5):
            net.step()
            got.append(net.output("S.OUTPUT").tolist())
        assert got == [[10, 20], [10, 20], [11, 18], [12, 16], [13, 14]]
    finally:
        net.close()


def test_copy_mode_and_outputsize_padding(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="In" outputsize="3" min="0" max="100" '
               'step="1"/>'
               '<module class="InitialValue" name="S" outputsize="3" data="5" wait="1" '
               'mode="copy"/>'
               '<connection source="In.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        assert np.array_equal(net.output("S.OUTPUT"), [5, 0, 0])
        net.step()
        assert np.array_equal(net.output("S.OUTPUT"), [5, 0, 0])
        for tick in range(1, 4):
            net.step()
            assert np.array_equal(net.output("S.OUTPUT"), [tick + 1] * 3)
    finally:
        net.close()


def test_update_gates_the_change(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="Flow" data="1"/>'
               '<module class="Sweep" name="U" min="0" max="1" step="1"/>'
               '<module class="InitialValue" name="S" data="0" wait="0"/>'
               '<connection source="Flow.OUTPUT" target="S.INPUT" delay="0"/>'
               '<connection source="U.OUTPUT" target="S.UPDATE" delay="0"/>')
    try:
        got = []
        for _ in range(6):                      # U: 1, 0, 1, 0, 1, 0
            net.step()
            got.append(float(net.output("S.OUTPUT")[0]))
        assert got == [1, 1, 2, 2, 3, 3]
    finally:
        net.close()


def test_stock_in_a_feedback_loop(tmp_path):
    # S(t+1) = S(t) + 0.5 * S(t): growth by half per tick, from 2
    net = load(tmp_path, '<module class="InitialValue" name="S" data="2" wait="1"/>'
               '<module class="Scale" name="Rate" factor="0.5"/>'
               '<connection source="S.OUTPUT" target="Rate.INPUT" delay="0"/>'
               '<connection source="Rate.OUTPUT" target="S.INPUT"/>')
    try:
        value = 2.0
        net.step()
        assert net.output("S.OUTPUT")[0] == value
        for _ in range(4):
            net.step()
            value *= 1.5
            assert np.isclose(net.output("S.OUTPUT")[0], value)
    finally:
        net.close()


def test_a_shorter_input_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="at least as many"):
        load(tmp_path, '<module class="Constant" name="Flow" data="1 2"/>'
             '<module class="InitialValue" name="S" data="1 2 3"/>'
             '<connection source="Flow.OUTPUT" target="S.INPUT"/>')


def test_a_longer_input_adds_its_first_elements_as_ikaros_2(tmp_path):
    # golden-v2 InitialValue "vector": a 4-element flow into the 1-element default stock
    net = load(tmp_path, '<module class="Constant" name="Flow" data="0.5 -1 2 0.25"/>'
               '<module class="InitialValue" name="S"/>'
               '<connection source="Flow.OUTPUT" target="S.INPUT" delay="0"/>')
    with net:
        got = []
        for _ in range(4):
            net.step()
            got.append(float(net.output("S.OUTPUT")[0]))
        assert got == [1, 1.5, 2, 2.5]                # data 1, then + 0.5 a tick
        assert sum("only the first 1 are used" in entry[3] for entry in net.log) == 1
