"""DESIGN §3 / §3.1: every build error is a ModelError naming the file, the line and the
element."""
import os

import pytest

import ikaros
from conformance_util import line_of, lines_of, load, model


def build_error(name: str) -> ikaros.ModelError:
    with pytest.raises(ikaros.ModelError) as info:
        load(name)
    e = info.value
    assert e.filename is not None and os.path.samefile(e.filename, model(name))
    assert name in str(e)
    assert str(e.line) in str(e)
    return e


def test_malformed_xml():
    e = build_error("err_malformed.ikg")
    assert e.line == line_of("err_malformed.ikg", "HERE")


def test_unknown_class():
    e = build_error("err_unknown_class.ikg")
    assert e.line == line_of("err_unknown_class.ikg", "HERE")
    assert "NoSuchClass" in str(e) and "Ghost" in str(e)


def test_unknown_source_module():
    e = build_error("err_unknown_source.ikg")
    assert e.line == line_of("err_unknown_source.ikg", "HERE")
    assert "Nowhere.OUTPUT" in str(e) and "connection" in str(e)


def test_unknown_source_output():
    e = build_error("err_unknown_output.ikg")
    assert e.line == line_of("err_unknown_output.ikg", "HERE")
    assert "NOSUCHOUTPUT" in str(e) and "connection" in str(e)


def test_unknown_target():
    e = build_error("err_unknown_target.ikg")
    assert e.line == line_of("err_unknown_target.ikg", "HERE")
    assert "G.Missing.INPUT" in str(e) and "connection" in str(e)


def test_zero_delay_cycle_names_every_module_and_a_connection_line():
    e = build_error("err_cycle.ikg")
    assert e.line in lines_of("err_cycle.ikg", "CYCLE")
    for name in ("Alpha", "Beta", "Gamma"):
        assert name in str(e)
    assert "Outside" not in str(e)
    assert "connection" in str(e)


def test_window_with_delay_zero_counts_for_cycles():
    e = build_error("err_cycle_window.ikg")
    assert e.line in lines_of("err_cycle_window.ikg", "CYCLE")[1:]   # the zero-delay ones
    assert "Alpha" in str(e) and "Beta" in str(e)


def test_required_input_unconnected_names_the_module_line():
    e = build_error("err_unconnected.ikg")
    assert e.line == line_of("err_unconnected.ikg", "HERE")
    assert "Lonely" in str(e) and "INPUT1" in str(e)


@pytest.mark.parametrize("name, text", [
    ("neg", "-1"), ("listneg", "1,-2"), ("desc", "3:1"), ("descbr", "[3:1]"),
    ("zerostep", "[0:3:0]"), ("emptybr", "[]"), ("emptyrange", "[2:2]"), ("text", "soon"),
])
def test_bad_delay(name, text):
    file = f"err_delay_{name}.ikg"
    e = build_error(file)
    assert e.line == line_of(file, "HERE")
    assert "delay" in str(e) and "connection" in str(e)
    assert f'"{text}"' in str(e)


def test_bad_bool_value():
    e = build_error("err_bad_bool.ikg")
    assert e.line == line_of("err_bad_bool.ikg", "HERE")
    assert "maybe" in str(e) and "flag" in str(e) and "Maybe" in str(e)


def test_bad_number_value():
    e = build_error("err_bad_number.ikg")
    assert e.line == line_of("err_bad_number.ikg", "HERE")
    assert "abc" in str(e) and "Word" in str(e)


def test_bad_int_value():
    e = build_error("err_bad_int.ikg")
    assert e.line == line_of("err_bad_int.ikg", "HERE")
    assert "12junk" in str(e) and "Junk" in str(e)


def test_duplicate_name_names_the_second_element():
    e = build_error("err_duplicate.ikg")
    assert e.line == line_of("err_duplicate.ikg", "HERE")
    assert "Twin" in str(e)


def test_duplicate_name_group_and_module():
    e = build_error("err_duplicate_group.ikg")
    assert e.line == line_of("err_duplicate_group.ikg", "HERE")
    assert '"G"' in str(e)


def test_unresolvable_size_names_the_buffer():
    e = build_error("err_unresolvable.ikg")
    assert e.line in lines_of("err_unresolvable.ikg", "HERE")
    assert "Ping" in str(e) or "Pong" in str(e)
    assert "OUTPUT" in str(e) or "INPUT" in str(e)


def test_two_windows_on_one_path():
    e = build_error("err_two_windows.ikg")
    assert e.line in lines_of("err_two_windows.ikg", "HERE")


def test_mixing_explicit_and_end_to_end_placement():
    e = build_error("err_mixed_placement.ikg")
    assert e.line in lines_of("err_mixed_placement.ikg", "HERE")
    assert "X.INPUT" in str(e)


@pytest.mark.parametrize("name, where", [
    ("err_in_group_class.ikg", "err_BadSub.ikg"),
    ("err_in_external.ikg", "err_BadSub.ikg"),
    ("err_in_include.ikg", "err_include_part.xml"),
])
def test_errors_in_other_files_name_that_file_and_line(name, where):
    with pytest.raises(ikaros.ModelError) as info:
        load(name)
    e = info.value
    assert os.path.samefile(e.filename, model(where))
    assert e.line == line_of(where, "HERE")
    assert where in str(e)
