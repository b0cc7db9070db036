"""Tests of the OneHotVector module (Ikaros 3 facts of issue 36: only -1 gives all zeros, any
other index is truncated and clipped into the output; Ikaros 2: an INPUT of several
elements gives all zeros, golden-v2 OneHotVector)."""
import pytest

import ikaros
from ikaros.module import WARNING
from ikaros.testing import load_body as load

BODY = ('<module class="Constant" name="I" data="{index}"/>'
        '<module class="OneHotVector" name="H" output_size="4" {attrs}/>'
        '<connection source="I.OUTPUT" target="H.INPUT" delay="0"/>{extra}')


def run(tmp_path, index, attrs="", extra="", ticks=1):
    net = load(tmp_path, BODY.format(index=index, attrs=attrs, extra=extra))
    try:
        net.run(ticks=ticks)
        warnings = [e[3] for e in net.log if e[1] == WARNING]
        return net.output("H.OUTPUT").tolist(), warnings
    finally:
        net.close()


@pytest.mark.parametrize("index, expected", [
    ("0", [1, 0, 0, 0]), ("2", [0, 0, 1, 0]), ("1.6", [0, 1, 0, 0]), ("12", [0, 0, 0, 1]),
    ("-1", [0, 0, 0, 0]), ("-0.5", [1, 0, 0, 0]), ("-3", [1, 0, 0, 0]), ("-1.5", [1, 0, 0, 0]),
    ("inf", [0, 0, 0, 1]), ("-inf", [1, 0, 0, 0])])
def test_the_index_is_truncated_as_in_ikaros_3(tmp_path, index, expected):
    # golden/README.md: a fraction is truncated (2.6 -> 2); issue 36: only exactly -1 gives
    # all zeros, any other index is clipped into 0 ... size - 1
    assert run(tmp_path, index) == (expected, [])
    assert run(tmp_path, index, 'value="3"')[0] == [3 * v for v in expected]


@pytest.mark.parametrize("index, expected", [
    ("0", [1, 0, 0, 0]), ("2", [0, 0, 1, 0]), ("1.6", [0, 0, 1, 0]), ("12", [0, 0, 0, 1]),
    ("-3", [1, 0, 0, 0]), ("inf", [0, 0, 0, 1]), ("-inf", [1, 0, 0, 0])])
def test_index_round_rounds_and_clamps(tmp_path, index, expected):
    assert run(tmp_path, index, 'index="round"') == (expected, [])


def test_an_index_input_of_more_than_one_element(tmp_path):
    with pytest.raises(ikaros.ModelError, match="INPUT must have one element"):
        load(tmp_path, BODY.format(index="1, 2", attrs="", extra=""), dialect="3")
    output, warnings = run(tmp_path, "1 2", ticks=2)        # Ikaros 2: all zeros
    assert output == [0, 0, 0, 0] and len(warnings) == 1


def test_the_default_output_size_is_ten(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="I" data="9"/>'
                         '<module class="OneHotVector" name="H"/>'
                         '<connection source="I.OUTPUT" target="H.INPUT" delay="0"/>')
    try:
        net.step()
        assert net.output("H.OUTPUT").tolist() == [0] * 9 + [1]
    finally:
        net.close()


def test_the_value_comes_from_the_parameter_or_the_value_input(tmp_path):
    assert run(tmp_path, "1", 'value="2.5"')[0] == [0, 2.5, 0, 0]
    extra = ('<module class="Constant" name="V" data="7"/>'
             '<connection source="V.OUTPUT" target="H.VALUE" delay="0"/>')
    assert run(tmp_path, "3", 'value="2.5"', extra)[0] == [0, 0, 0, 7]


def test_a_nan_index_gives_zeros_and_one_warning(tmp_path):
    output, warnings = run(tmp_path, "nan", ticks=3)
    assert output == [0, 0, 0, 0]
    assert warnings == ["the index is not a number; the output is all zeros"]


def test_output_size_below_one_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match='parameter "output_size" of H: 0 is below '
                                                'minimum 1'):
        load(tmp_path, '<module class="Constant" name="I" data="0"/>'
                       '<module class="OneHotVector" name="H" output_size="0"/>'
                       '<connection source="I.OUTPUT" target="H.INPUT"/>')
