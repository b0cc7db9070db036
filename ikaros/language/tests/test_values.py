import numpy as np
import pytest

from ikaros.language.expressions import ExpressionError, evaluate_arithmetic, is_arithmetic
from ikaros.language.values import (ValueError_, parse_bool, parse_delays, parse_int,
                                    parse_matrix, parse_number, split_selectors, value_text)


@pytest.mark.parametrize("text,expected", [
    ("true", True), ("YES", True), ("on", True), ("1", True),
    ("false", False), ("No", False), ("off", False), ("0", False)])
def test_bool_words(text, expected):
    assert parse_bool(text) is expected


def test_bool_rejects_other_words():
    with pytest.raises(ValueError_, match='"maybe" is not a boolean'):
        parse_bool("maybe")


def test_numbers_and_arithmetic():
    assert parse_number("2.5") == 2.5
    assert parse_number("5*10+1") == 51
    assert parse_number("888-38/2") == 869
    assert parse_number("-(2+3)*2") == -10
    assert parse_int("+7") == 7
    with pytest.raises(ValueError_):
        parse_int("2.5")
    with pytest.raises(ValueError_):
        parse_number("abc")


def test_arithmetic_errors():
    with pytest.raises(ExpressionError, match="division by zero"):
        evaluate_arithmetic("1/0")
    with pytest.raises(ExpressionError, match="unmatched parenthesis"):
        evaluate_arithmetic("(1+2")
    assert is_arithmetic("1+2") and not is_arithmetic("T-INPUT") and not is_arithmetic("-3")


def test_matrix_literals():
    assert parse_matrix("1 2 3").tolist() == [1, 2, 3]
    assert parse_matrix("1, 2, 3").shape == (3,)
    assert parse_matrix("1 2; 3 4;").tolist() == [[1, 2], [3, 4]]
    assert parse_matrix("1, 2; 3").tolist() == [[1, 2], [3, 0]]
    assert parse_matrix("1 2 # first row\n; 3 4").tolist() == [[1, 2], [3, 4]]
    m = parse_matrix("[[[1,2],[3,4]],[[5,6],[7,8]]]")
    assert m.shape == (2, 2, 2) and m[1, 0, 1] == 6
    assert parse_matrix("1+1, 2*3").tolist() == [2, 6]
    assert parse_matrix("1 2").dtype == np.float32
    with pytest.raises(ValueError_):
        parse_matrix("1, , 2")
    with pytest.raises(ValueError_):
        parse_matrix("[[1,2],[3]]")


@pytest.mark.parametrize("text,expected", [
    ("0", [0]), ("1", [1]), ("1:3", [1, 2, 3]), ("1,3,5:7", [1, 3, 5, 6, 7]),
    ("[1:4]", [1, 2, 3]), ("[0:5:2]", [0, 2, 4]), ("[2]", [2]), ("3:3", [3])])
def test_delays(text, expected):
    assert parse_delays(text) == expected


@pytest.mark.parametrize("text,message", [
    ("-1", "non-negative"), ("[0:3:0]", "positive increment"), ("[3:0]", "ascending"),
    ("[0][1]", "one-dimensional"), ("[]", "must not be empty"), ("", "must not be empty"),
    ("3:1", "ascending"), ("a", "whole number")])
def test_bad_delays(text, message):
    with pytest.raises(ValueError_, match=message):
        parse_delays(text)


def test_selectors():
    assert split_selectors("A.OUTPUT") == ("A.OUTPUT", None)
    assert split_selectors("A.OUTPUT[0:2][]") == ("A.OUTPUT", [("range", 0, 2, 1), ("all",)])
    assert split_selectors("A.OUTPUT[1]") == ("A.OUTPUT", [("index", 1)])
    assert split_selectors("A.OUTPUT[0:3:-1]") == ("A.OUTPUT", [("range", 0, 3, -1)])
    with pytest.raises(ValueError_, match="zero increment"):
        split_selectors("A.OUTPUT[0:3:0]")
    with pytest.raises(ValueError_, match="non-negative, ordered"):
        split_selectors("A.OUTPUT[3:1]")


def test_value_text():
    assert value_text(True) == "true"
    assert value_text(2.0) == "2"
    assert value_text(np.array([[1, 2], [3, 4.5]])) == "1, 2; 3, 4.5"
    assert value_text([1, 2]) == "1, 2"
