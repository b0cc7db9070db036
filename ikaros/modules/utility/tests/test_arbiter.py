"""Tests of the Arbiter module. Ikaros 2 never writes its VALUE output (golden-v2 Arbiter: 0);
most tests here read value_output="strength", this project's sum of the absolute state."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def _body(inputs, values=None, attrs="", by_row=False):
    """Constants I1.. (and V1..) connected to Arbiter A."""
    row = ' by_row="yes"' if by_row else ""
    lines = [f'<module class="Arbiter" name="A" no_of_inputs="{len(inputs)}" '
             f'value_output="strength" {attrs}{row}/>']
    for k, data in enumerate(inputs, 1):
        lines.append(f'<module class="Constant" name="I{k}" data="{data}"/>')
        lines.append(f'<connection source="I{k}.OUTPUT" target="A.INPUT_{k}" delay="0"/>')
    for k, data in enumerate(values or [], 1):
        lines.append(f'<module class="Constant" name="V{k}" data="{data}"/>')
        lines.append(f'<connection source="V{k}.OUTPUT" target="A.VALUE_{k}" delay="0"/>')
    return "\n".join(lines)


def _outputs(net):
    return {n: net.output(f"A.{n}").copy() for n in
            ("AMPLITUDES", "ARBITRATION", "SMOOTHED", "NORMALIZED", "OUTPUT", "VALUE")}


def test_wta_on_city_block_norms(tmp_path):
    net = load(tmp_path, _body(["1 -2", "0.5 0.5", "-3 0"]))
    try:
        net.step()
        o = _outputs(net)
        assert np.array_equal(o["AMPLITUDES"], [3, 1, 3])
        assert np.array_equal(o["ARBITRATION"], [3, 0, 0])        # a tie: INPUT_1 wins
        assert np.array_equal(o["NORMALIZED"], [1, 0, 0])
        assert np.array_equal(o["OUTPUT"], [1, -2])
        assert o["VALUE"].shape == (1,) and o["VALUE"][0] == 3
    finally:
        net.close()


def test_ikaros_2_value_output_is_0(tmp_path):
    body = _body(["1 -2", "0.5 0.5"]).replace(' value_output="strength"', "")
    with load(tmp_path, body) as net:
        net.step()
        assert net.output("A.VALUE").tolist() == [0]
        assert net.output("A.OUTPUT").tolist() == [1, -2]


def test_euclidean_metric(tmp_path):
    net = load(tmp_path, _body(["3 4", "1 6", "0 0"], attrs='metric="2"'))
    try:
        net.step()
        o = _outputs(net)
        assert np.allclose(o["AMPLITUDES"], [5, np.sqrt(37), 0])
        assert np.array_equal(o["OUTPUT"], [1, 6])
    finally:
        net.close()


def test_values_override_norms_and_softmax_blends(tmp_path):
    net = load(tmp_path, _body(["10 0", "0 10"], values=["1", "3"],
                               attrs='arbitration="softmax" softmax_exponent="2"'))
    try:
        net.step()
        o = _outputs(net)
        assert np.array_equal(o["AMPLITUDES"], [1, 3])
        assert np.array_equal(o["ARBITRATION"], [1, 9])
        assert np.allclose(o["NORMALIZED"], [0.1, 0.9])
        assert np.allclose(o["OUTPUT"], [1, 9])
        assert np.isclose(o["VALUE"][0], 10)
    finally:
        net.close()


def test_hierarchy_picks_the_highest_active_input(tmp_path):
    net = load(tmp_path, _body(["1", "2", "3", "4"], values=["5", "0.1", "7", "0"],
                               attrs='arbitration="hierarchy"'))
    try:
        net.step()
        o = _outputs(net)
        assert np.allclose(o["ARBITRATION"], [0, 0, 7, 0])
        assert np.array_equal(o["OUTPUT"], [3])
    finally:
        net.close()
    (tmp_path / "b").mkdir()
    net = load(tmp_path / "b", _body(["1", "2"], values=["0", "0"],
                                     attrs='arbitration="hierarchy"'))
    try:
        net.step()
        assert np.array_equal(net.output("A.ARBITRATION"), [0, 0])
        assert np.array_equal(net.output("A.OUTPUT"), [0])     # nothing active: weights 0
    finally:
        net.close()


def test_hysteresis_keeps_the_winner_until_clearly_beaten(tmp_path):
    # VALUE_1 is 5; VALUE_2 ramps 0, 1, 2, ... (Sweep, delay 0: k+1 on tick k).
    net = load(tmp_path,
               '<module class="Arbiter" name="A" arbitration="hysteresis" '
               'hysteresis_threshold="3"/>\n'
               '<module class="Constant" name="I1" data="1"/>\n'
               '<module class="Constant" name="I2" data="2"/>\n'
               '<module class="Constant" name="V1" data="5"/>\n'
               '<module class="Sweep" name="V2" min="0" max="100" step="1"/>\n'
               '<connection source="I1.OUTPUT" target="A.INPUT_1" delay="0"/>\n'
               '<connection source="I2.OUTPUT" target="A.INPUT_2" delay="0"/>\n'
               '<connection source="V1.OUTPUT" target="A.VALUE_1" delay="0"/>\n'
               '<connection source="V2.OUTPUT" target="A.VALUE_2" delay="0"/>')
    try:
        chosen = []
        for _ in range(10):
            net.step()
            chosen.append(float(net.output("A.OUTPUT")[0]))
        # V2 = 1..10; the switch needs V2 > 5 + 3, i.e. from V2 = 9 (tick 8).
        assert chosen == [1] * 8 + [2] * 2
    finally:
        net.close()


def test_smoothing_with_switch_time(tmp_path):
    net = load(tmp_path, _body(["1 1", "0 4"], attrs='switch_time="4"'))
    try:
        s = np.zeros(2)
        arbitration = np.array([0, 4.0])
        for _ in range(6):
            net.step()
            s = 0.75 * s + 0.25 * arbitration
            w = s / np.abs(s).sum()
            assert np.allclose(net.output("A.SMOOTHED"), s)
            assert np.allclose(net.output("A.NORMALIZED"), w)
            assert np.allclose(net.output("A.OUTPUT"), w[0] * np.array([1, 1])
                               + w[1] * np.array([0, 4]))
            assert np.isclose(net.output("A.VALUE")[0], s.sum())
    finally:
        net.close()


def test_alpha_smoothing(tmp_path):
    net = load(tmp_path, _body(["2", "1"], attrs='alpha="0.5"'))
    try:
        for expected in (1.0, 1.5, 1.75):
            net.step()
            assert np.allclose(net.output("A.SMOOTHED"), [expected, 0])
            assert np.allclose(net.output("A.OUTPUT"), [2])
    finally:
        net.close()


def test_by_row(tmp_path):
    net = load(tmp_path, _body(["1 1; 0 0; 5 5", "0 3; 1 0; 5 5"], by_row=True))
    try:
        net.step()
        o = _outputs(net)
        assert o["AMPLITUDES"].shape == (3, 2) and o["VALUE"].shape == (3,)
        assert np.array_equal(o["AMPLITUDES"], [[2, 3], [0, 1], [10, 10]])
        assert np.array_equal(o["NORMALIZED"], [[0, 1], [0, 1], [1, 0]])
        assert np.array_equal(o["OUTPUT"], [[0, 3], [1, 0], [5, 5]])
        assert np.array_equal(o["VALUE"], [3, 1, 10])
    finally:
        net.close()


def test_by_row_with_one_value_per_row(tmp_path):
    net = load(tmp_path, _body(["1 1; 2 2", "3 3; 4 4"], values=["1 0", "0 1"], by_row=True))
    try:
        net.step()
        assert np.array_equal(net.output("A.OUTPUT"), [[1, 1], [4, 4]])
    finally:
        net.close()


def test_some_values_connected_is_an_error(tmp_path):
    body = _body(["1", "2"]) + ('\n<module class="Constant" name="V" data="1"/>'
                                '\n<connection source="V.OUTPUT" target="A.VALUE_1" delay="0"/>')
    with pytest.raises(ikaros.ModelError, match="all VALUE inputs"):
        load(tmp_path, body)


def test_different_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same size"):
        load(tmp_path, _body(["1 2", "1 2 3"]))


# --- the Ikaros 3 interface: one stacked INPUT ------------------------------------------------

def _stacked_body(inputs, attrs=""):
    """Constants I1.. all connected to Arbiter A's INPUT, in order."""
    lines = [f'<module class="Arbiter" name="A" value_output="strength" {attrs}/>']
    for k, data in enumerate(inputs, 1):
        lines.append(f'<module class="Constant" name="I{k}" data="{data}"/>')
        lines.append(f'<connection source="I{k}.OUTPUT" target="A.INPUT" delay="0"/>')
    return "\n".join(lines)


def test_v3_stacked_input_gives_the_same_as_numbered_inputs(tmp_path):
    inputs = ["1 -2", "0.5 0.5", "-3 0.5"]
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    v2 = load(tmp_path / "a", _body(inputs))
    v3 = load(tmp_path / "b", _stacked_body(inputs))    # no_of_inputs is not needed
    try:
        v2.step()
        v3.step()
        a, b = _outputs(v2), _outputs(v3)
        assert np.array_equal(b["AMPLITUDES"], [3, 1, 3.5])
        assert np.array_equal(b["ARBITRATION"], [0, 0, 3.5])
        assert np.array_equal(b["OUTPUT"], [-3, 0.5])
        for name in a:
            assert np.array_equal(a[name], b[name]), name
    finally:
        v2.close()
        v3.close()


def test_v3_stacked_input_softmax_by_row(tmp_path):
    net = load(tmp_path, _stacked_body(["1 0; 0 2", "0 3; 1 0"],
                                       'arbitration="softmax" softmax_exponent="1" '
                                       'by_row="yes"'))
    try:
        net.step()
        o = _outputs(net)
        assert np.array_equal(o["AMPLITUDES"], [[1, 3], [2, 1]])
        assert np.allclose(o["NORMALIZED"], [[0.25, 0.75], [2 / 3, 1 / 3]])
        assert np.allclose(o["OUTPUT"], [[0.25, 2.25], [1 / 3, 4 / 3]])
        assert np.array_equal(o["VALUE"], [4, 3])
    finally:
        net.close()


def test_both_interfaces_at_once_is_an_error(tmp_path):
    body = _stacked_body(["1", "2"]) + \
        '\n<connection source="I1.OUTPUT" target="A.INPUT_1" delay="0"/>'
    with pytest.raises(ikaros.ModelError, match="not both: INPUT_1 is connected"):
        load(tmp_path, body)


def test_v2_numbered_input_left_unconnected_is_an_error(tmp_path):
    body = _body(["1", "2"]).replace('target="A.INPUT_2"', 'target="A.VALUE_2"')
    with pytest.raises(ikaros.ModelError, match='input "INPUT_2" is not connected'):
        load(tmp_path, body)


def _v3(tmp_path, attrs, values=None):
    body = ('<module class="Constant" name="A" data="1, 2"/>'
            '<module class="Constant" name="B" data="3, -0.5"/>'
            f'<module class="Arbiter" name="R" {attrs}/>'
            '<connection source="A.OUTPUT" target="R.INPUT" delay="0"/>'
            '<connection source="B.OUTPUT" target="R.INPUT" delay="0"/>')
    if values is not None:
        body += (f'<module class="Constant" name="V" data="{values}"/>'
                 '<connection source="V.OUTPUT" target="R.VALUE" delay="0"/>')
    net = load(tmp_path, body, dialect="3")
    try:
        net.step()
        return {k: net.output(f"R.{k}").copy() for k in
                ("AMPLITUDES", "ARBITRATION", "SMOOTHED", "NORMALIZED", "OUTPUT")}
    finally:
        net.close()


def test_ikaros_3_values_in_one_connection_are_concatenated(tmp_path):
    # MODULES-V3 §24: without stack_values one VALUE connection holds every candidate's value
    out = _v3(tmp_path, "", values="5, 1")
    assert out["AMPLITUDES"].tolist() == [5, 1] and out["ARBITRATION"].tolist() == [5, 0]
    assert out["OUTPUT"].tolist() == [1, 2]


def test_ikaros_3_softmax_of_signed_values_normalizes_by_the_signed_sum(tmp_path):
    # softmax_exponent 3: (-1)^3 = -1, 2^3 = 8; NORMALIZED = SMOOTHED / 7 (not / 9)
    out = _v3(tmp_path, 'arbitration="softmax" softmax_exponent="3"', values="-1, 2")
    assert out["ARBITRATION"].tolist() == [-1, 8]
    assert np.allclose(out["NORMALIZED"], [-1 / 7, 8 / 7])
    assert np.allclose(out["OUTPUT"], np.array([-1, 8]) @ np.array([[1, 2], [3, -0.5]]) / 7)


def test_ikaros_3_a_value_per_candidate_is_required(tmp_path):
    with pytest.raises(ikaros.ModelError, match="one per candidate"):
        _v3(tmp_path, "", values="1, 2, 3")
