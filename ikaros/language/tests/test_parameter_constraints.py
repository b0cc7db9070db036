"""Ikaros 3 parameter constraints in class files: ``min``/``max`` and a matrix's
``shape``/``size``."""
from pathlib import Path

import numpy as np
import pytest

import ikaros

from ikaros.description import ParameterSpec
from ikaros.errors import ModelError
from ikaros.kernel.ranges import check_parameter, fit_shape
from ikaros.language.classfile import parameter_spec
from ikaros.language.reader import read_file
from ikaros.language.values import ValueError_


def _spec(tmp_path, element):
    path = tmp_path / "C.ikc"
    path.write_text(f'<class name="C">{element}</class>')
    return parameter_spec(next(read_file(str(path)).elements("parameter")))


def test_min_and_max_become_the_range(tmp_path):
    spec = _spec(tmp_path, '<parameter name="n" type="int" min="1" max="1e3"/>')
    assert spec.range == (1.0, 1000.0) and spec.shape is None
    assert _spec(tmp_path, '<parameter name="x" min="-2"/>').range == (-2.0, None)
    assert _spec(tmp_path, '<parameter name="x"/>').range is None


def test_values_outside_are_named_with_the_bound():
    spec = ParameterSpec("n", "number", range=(1, 5))
    check_parameter(1.0, spec)
    check_parameter(5.0, spec)
    with pytest.raises(ValueError_, match="^0 is below minimum 1$"):
        check_parameter(0.0, spec)
    with pytest.raises(ValueError_, match=r"^5.5 is above maximum 5$"):
        check_parameter(5.5, spec)


def test_shape_and_its_alias_size_are_read_for_matrices(tmp_path):
    assert _spec(tmp_path, '<parameter name="m" type="matrix" shape="@rows,3"/>').shape == \
        "@rows,3"
    assert _spec(tmp_path, '<parameter name="m" type="matrix" size="4"/>').shape == "4"


def test_a_bad_bound_or_a_shape_on_a_number_is_an_error_at_the_element(tmp_path):
    with pytest.raises(ModelError, match=r'C.ikc:1: <parameter name="x">: min: "low"'):
        _spec(tmp_path, '<parameter name="x" min="low"/>')
    with pytest.raises(ModelError, match='shape="3" is for matrix parameters'):
        _spec(tmp_path, '<parameter name="x" type="number" shape="3"/>')


def test_fit_shape_zero_fills_in_row_major_order_and_refuses_too_many():
    assert np.array_equal(fit_shape(np.array([[1, 2], [3, 0]]), (2, 3)),
                          [[1, 2, 3], [0, 0, 0]])
    assert fit_shape(np.zeros((0,)), (4, 3)).shape == (4, 3)
    with pytest.raises(ValueError_, match="^Matrix parameter value has 4 elements but shape "
                                          "3 only allows 3$"):
        fit_shape(np.array([1, 2, 3, 4]), (3,))


SUPPORT = Path(__file__).resolve().parents[2] / "testsupport"


def _support_model(tmp_path, attrs=""):
    (tmp_path / "m.ikg").write_text(
        f'<group name="T" support="{SUPPORT}"><module class="ShapedParameterTestModule" '
        f'name="M" path="@support" {attrs}/></group>')
    return ikaros.load(str(tmp_path / "m.ikg"))


def test_a_shaped_parameter_keeps_its_shape_when_set_while_running(tmp_path):
    net = _support_model(tmp_path, 'max_sequences="2"')
    try:
        assert net.parameter("M.sequences").shape == (2, 3)
        net.set_parameter("M.sequences", "1 2 3 4")
        assert net.parameter("M.sequences").tolist() == [[1, 2, 3], [4, 0, 0]]
        with pytest.raises(ValueError, match="has 7 elements but shape 2,3 only allows 6"):
            net.set_parameter("M.sequences", "1 2 3 4 5 6 7")
        with pytest.raises(ValueError, match="1.5 is above maximum 1"):
            net.set_parameter("M.gain", 1.5)
        assert net.parameter("M.gain") == 0.5
    finally:
        net.close()


def test_the_class_text_shows_bounds_and_shape():
    from ikaros.kernel.classes import ClassRegistry
    text = ClassRegistry([str(SUPPORT)]).find("ShapedParameterTestModule").description() \
        .to_text()
    assert "max_sequences (number, default '4', range 1..10)" in text
    assert "sequences (matrix, default None, shape @max_sequences,3)" in text
