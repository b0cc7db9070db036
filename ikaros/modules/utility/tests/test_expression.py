"""Tests of the Expression module."""
import numpy as np
import pytest

import ikaros
from ikaros.module import WARNING
from ikaros.testing import load_body as load

# x sweeps from 0 by 1 (x = k + 1 on tick k, delay 0); y is a constant.
BODY = ('<module class="Sweep" name="X" min="0" max="1000" step="1" outputsize="3"/>\n'
        '<module class="Constant" name="Y" data="{y}"/>\n'
        '<module class="Expression" name="E" expression="{expr}" inputs="x,y"/>\n'
        '<connection source="X.OUTPUT" target="E.x" delay="0"/>\n'
        '<connection source="Y.OUTPUT" target="E.y" delay="0"/>')


def _check(tmp_path, expr, reference, y="1 2 -3", ticks=4):
    net = load(tmp_path, BODY.format(expr=expr.replace("<", "&lt;").replace(">", "&gt;"),
                                     y=y))
    try:
        yv = np.array(y.split(), np.float64)
        for k in range(ticks):
            net.step()
            x = np.full(3, k + 1.0)
            with np.errstate(all="ignore"):
                expected = reference(x, yv)
            assert np.allclose(net.output("E.OUTPUT"), expected, atol=1e-5), (expr, k)
        return net.log
    finally:
        net.close()


@pytest.mark.parametrize("expr, reference", [
    ("x + y", lambda x, y: x + y),
    ("x*y - 2^3", lambda x, y: x * y - 8),
    ("-x^2 + y", lambda x, y: -(x ** 2) + y),
    ("2^3^2", lambda x, y: 0 * x + 512),
    ("(x + y) * (x - y) / 2", lambda x, y: (x + y) * (x - y) / 2),
    ("2x + 3(y - 1)", lambda x, y: 2 * x + 3 * (y - 1)),
    ("sin(pi * x / 4) + cos(y) * exp(-x)", lambda x, y: np.sin(np.pi * x / 4)
     + np.cos(y) * np.exp(-x)),
    ("sqrt(x) + abs(y) + log(x) + tanh(y)", lambda x, y: np.sqrt(x) + np.abs(y) + np.log(x)
     + np.tanh(y)),
    ("max(x, y, 2) - min(x, y)", lambda x, y: np.maximum(np.maximum(x, y), 2)
     - np.minimum(x, y)),
    ("clamp(0, y, 1) + pow(x, 0.5) + atan2(y, x)", lambda x, y: np.clip(y, 0, 1)
     + np.sqrt(x) + np.arctan2(y, x)),
    ("x > 2 and y > 0", lambda x, y: ((x > 2) & (y > 0)).astype(float)),
    ("not (x <= 1) or y == -3", lambda x, y: ((x > 1) | (y == -3)).astype(float)),
    ("y < 0 ? x : -x", lambda x, y: np.where(y < 0, x, -x)),
    ("if(y != 2, 10, 20) + x % 3", lambda x, y: np.where(y != 2, 10, 20) + np.fmod(x, 3)),
    ("floor(y / 2) + ceil(x / 3) + round(2.5)", lambda x, y: np.floor(y / 2)
     + np.ceil(x / 3) + 3),
    ("1.5e1 + .5", lambda x, y: 0 * x + 15.5),
])
def test_formulas(tmp_path, expr, reference):
    _check(tmp_path, expr, reference)


def test_division_by_zero_gives_zero_and_one_warning(tmp_path):
    log = _check(tmp_path, "x / y + y % y", lambda x, y: np.where(y == 0, 0, x / np.where(
        y == 0, 1, y)), y="0 2 0")
    warnings = [e for e in log if e[1] == WARNING and e[2].split(".")[-1] == "E"]
    assert len(warnings) == 1 and "division by zero" in warnings[0][3]


def test_results_that_are_not_finite_become_zero(tmp_path):
    log = _check(tmp_path, "sqrt(y) + log(y)", lambda x, y: np.where(
        y > 0, np.sqrt(np.abs(y)) + np.log(np.abs(y)), 0), y="-1 4 0")
    assert len([e for e in log if e[1] == WARNING and e[2].split(".")[-1] == "E"]) == 1


def test_default_is_x_and_keeps_the_shape(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
               '<module class="Expression" name="E"/>\n'
               '<connection source="C.OUTPUT" target="E.x" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("E.OUTPUT"), [[1, 2], [3, 4]])
    finally:
        net.close()


def test_concatenated_connections_and_a_constant_expression(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1"/>\n'
               '<module class="Constant" name="B" data="2"/>\n'
               '<module class="Constant" name="C" data="10 20"/>\n'
               '<module class="Expression" name="E" expression="a * b" inputs="a, b"/>\n'
               '<module class="Expression" name="K" expression="pi" inputs="a"/>\n'
               '<module class="Expression" name="N" expression="3" inputs=""/>\n'
               '<connection source="A.OUTPUT" target="E.a" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="E.a" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="E.b" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="K.a" delay="0"/>')
    try:
        net.step()
        # a = [B, A] = [2, 1]: the connection declared last comes first (Ikaros 2)
        assert np.array_equal(net.output("E.OUTPUT"), [20, 20])
        assert np.allclose(net.output("K.OUTPUT"), [np.pi, np.pi])
        assert np.array_equal(net.output("N.OUTPUT"), [3])
    finally:
        net.close()


@pytest.mark.parametrize("expr, message", [
    ("x +", "position"), ("foo(x)", "unknown function"), ("z + 1", "unknown name"),
    ("(x", "expected"), ("x y", "unexpected"), ("max()", "arguments"),
    ("__import__(x)", "unknown function"), ("x; 1", "unexpected character"),
])
def test_bad_expressions_are_model_errors(tmp_path, expr, message):
    with pytest.raises(ikaros.ModelError, match=message):
        load(tmp_path, f'<module class="Expression" name="E" expression="{expr}"/>')


def test_inputs_of_different_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same size"):
        load(tmp_path, BODY.format(expr="x + y", y="1 2"))


def test_reserved_variable_name_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="cannot be used"):
        load(tmp_path, '<module class="Expression" name="E" expression="tick" inputs="tick"/>')
