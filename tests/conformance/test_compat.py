"""Issue 11: what the original Ikaros accepts, this accepts (with a warning naming file and
line); ``strict=True`` makes each such warning an error."""
import os

import pytest

import ikaros
import ikaros.module
from conformance_util import line_of, load, model, same


def warnings_of(net, name):
    """{line: [messages]} of a loaded model's warnings in file ``name``."""
    out = {}
    for w in net.warnings:
        assert w.filename is not None
        if os.path.basename(w.filename) == name:
            out.setdefault(w.line, []).append(w.message)
    return out


# --- 1. XML leniency ----------------------------------------------------------------------
def test_xml_leniency_reads_the_values_the_original_reads():
    net = load("compat_xml.ikg", quiet=True)
    assert (net.parameter("Glued.p"), net.parameter("Glued.q")) == (3, 4)
    assert (net.parameter("Twice.p"), net.parameter("Twice.q")) == (5, 6)
    assert net.parameter("Amp.s") == "R&D"
    assert net.parameter("Named.s") == "<&A&nbsp;"     # an unknown entity stays as written
    assert net.top.attrs["title"] == "Tom & Jerry"
    net.step()
    same(net.output("Out.OUTPUT"), [3, 4])


def test_xml_leniency_warns_with_file_and_line():
    net = load("compat_xml.ikg", quiet=True)
    found = warnings_of(net, "compat_xml.ikg")
    name = "compat_xml.ikg"
    assert found == {
        line_of(name, "Tom & Jerry"): ["a bare & is read as a literal & (write &amp;)"],
        line_of(name, "GLUED"): ['no space before attribute "q"'],
        line_of(name, "REPEATED"): ['attribute "p" repeated; the first value, "5", is kept'],
        line_of(name, "AMPERSAND"): ["a bare & is read as a literal & (write &amp;)"],
        line_of(name, "ENTITY"): ["a bare & is read as a literal & (write &amp;)"],
    }
    repeated = [w for w in net.warnings if "repeated" in w.message][0]
    assert repeated.element == '<module name="Twice">'
    assert str(repeated) == (f'{model(name)}:{line_of(name, "REPEATED")}: warning: '
                             f'<module name="Twice">: attribute "p" repeated; the first '
                             f'value, "5", is kept')


def test_load_warnings_are_in_the_log_the_web_ui_shows():
    net = load("compat_xml.ikg", quiet=True)
    warnings = [entry for entry in net.log if entry[1] == ikaros.module.WARNING]
    assert [message for _, _, _, message in warnings] == [w.located() for w in net.warnings]
    assert (f'{model("compat_xml.ikg")}:{line_of("compat_xml.ikg", "GLUED")}: '
            f'<module name="Glued">: no space before attribute "q"') in [w[3] for w in warnings]


def test_xml_leniency_is_an_error_when_strict():
    with pytest.raises(ikaros.ModelError) as e:
        load("compat_xml.ikg", strict=True)
    assert e.value.line == line_of("compat_xml.ikg", "Tom & Jerry")
    assert "bare &" in str(e.value) and "strict" in str(e.value)


def test_xml_leniency_prints_warnings_unless_quiet(capsys):
    load("compat_xml.ikg")
    err = capsys.readouterr().err
    assert f'{model("compat_xml.ikg")}:{line_of("compat_xml.ikg", "GLUED")}: warning: ' in err
    load("compat_xml.ikg", quiet=True)
    assert capsys.readouterr().err == ""


def test_a_leniently_read_file_is_saved_clean(tmp_path):
    net = load("compat_xml.ikg", quiet=True)
    for helper in ("Par.py", "Sink.py"):
        with open(model(helper)) as src, open(tmp_path / helper, "w") as dst:
            dst.write(src.read())
    net.save(str(tmp_path / "saved.ikg"))
    again = ikaros.load(str(tmp_path / "saved.ikg"), strict=True)
    assert again.warnings == []
    assert (again.parameter("Glued.p"), again.parameter("Twice.p")) == (3, 5)
    assert again.parameter("Named.s") == "<&A&nbsp;"


# --- 2. values the original treats as unset ---------------------------------------------
def test_empty_and_undefined_values_take_the_class_default():
    net = load("compat_unset.ikg", quiet=True)
    p = net.parameter
    assert (p("Empty.p"), p("Empty.k"), p("Empty.flag"), p("Empty.mode")) == (1.0, 4, False, "a")
    assert p("Empty.s") == ""                  # an empty string is a value
    assert (p("Inherit.p"), p("Inherit.q")) == (8, 2)     # q="" on the group: unset
    assert (p("Undefined.p"), p("Undefined.q"), p("Undefined.s")) == (1.0, 3, "")


def test_unset_values_warn_with_file_and_line():
    net = load("compat_unset.ikg", quiet=True)
    name = "compat_unset.ikg"
    found = warnings_of(net, name)
    assert sorted(found) == [line_of(name, m) for m in ("GROUP", "EMPTY", "UNDEFINED",
                                                        "NAMELESS", "DELAY")]
    assert found[line_of(name, "DELAY")] == ["an empty delay means the default, 1"]
    assert len(found[line_of(name, "EMPTY")]) == 4     # p, k, flag, mode (not s)
    assert 'variable "@gain" is not defined; read as an empty value' in \
        found[line_of(name, "UNDEFINED")]
    assert found[line_of(name, "NAMELESS")] == [
        'a <module> without a name takes its class name "Par"']
    with pytest.raises(ikaros.ModelError) as e:
        load(name, strict=True)
    assert e.value.line == line_of(name, "NAMELESS")     # the tree is built first


def test_a_module_without_name_takes_its_class_name_and_names_with_spaces_work():
    net = load("compat_unset.ikg", quiet=True)
    net.step()
    same(net.output("Par.OUTPUT"), [9, 10])
    same(net.output("Out2.OUTPUT"), [9, 10])
    same(net.output("Group Inner.In Side.OUTPUT"), [5, 6])
    same(net.output("Group Inner.Sink.OUTPUT"), [5, 6])
    same(net.output("Out.OUTPUT"), [5, 6])
    same(net.output("QS.OUTPUT"), [100])           # delay="": the default delay, 1


def test_unset_values_are_saved_clean(tmp_path):
    net = load("compat_unset.ikg", quiet=True)
    for helper in ("Par.py", "Sink.py", "Seq.py"):
        with open(model(helper)) as src, open(tmp_path / helper, "w") as dst:
            dst.write(src.read())
    net.save(str(tmp_path / "saved.ikg"))
    text = (tmp_path / "saved.ikg").read_text()
    assert '<module class="Par" name="Par" p="9" q="10"/>' in text
    assert '<module class="Par" name="Empty" s=""/>' in text
    again = ikaros.load(str(tmp_path / "saved.ikg"), quiet=True)
    lines = text.splitlines()
    expected = {i for i, t in enumerate(lines, 1) if 'name="Unset"' in t or '"Undefined"' in t}
    assert {w.line for w in again.warnings} == expected   # q="" on the group, @gain, @label
    assert again.parameter("Empty.p") == 1.0


def test_an_undefined_variable_in_arithmetic_is_an_error():
    with pytest.raises(ikaros.ModelError) as e:
        load("err_undefined_arithmetic.ikg")
    assert e.value.line == line_of("err_undefined_arithmetic.ikg", "HERE")
    assert 'Variable "@gain" not defined.' in str(e.value)


# --- 4. Ikaros 3 class-file forms ---------------------------------------------------------
def test_ikaros_3_class_file_forms():
    net = load("compat_ikc/compat_ikc_forms.ikg", strict=True)
    assert net.parameter("Label.type") == 2          # a label gives its index
    assert net.parameter("Label.tick") == 3          # named like Module.tick
    net.step()
    same(net.output("Default.OUTPUT"), [1, 7, 1, 5])
    same(net.output("Label.OUTPUT"), [2, 3, 0, 7])
    same(net.output("Index.OUTPUT"), [0, 7, 1, 5])
    net.set_parameter("Index.type", "sine")
    net.set_parameter("Index.tick", 9)
    net.step()
    same(net.output("Index.OUTPUT"), [0, 9, 1, 5])
    same(net.output("S.OUTPUT"), [15, 30])          # Pair.ikc: a group used as a class
    assert net.parameter("P.K2.data").tolist() == [10]


def test_an_option_that_is_not_listed_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match='"saw" is not one of sine/square/triangle'):
        load("compat_ikc/compat_ikc_forms.ikg", type="saw")


# --- 6. two rules of DESIGN §3 ------------------------------------------------------------
def test_a_matrix_row_may_mix_commas_and_white_space():
    net = load("compat_rules.ikg", strict=True)
    same(net.output("Mixed.OUTPUT"), [[1, 2, 3], [4, 5, 6]])


def test_a_qualified_attribute_reaches_a_module_at_any_depth():
    net = load("compat_rules.ikg", strict=True)
    assert net.parameter("A.B.Deep.p") == 11       # two groups down
    assert net.parameter("A.C.Near.p") == 21       # the nearer group wins
    assert net.parameter("A.D.Par.q") == 31        # a nearer plain attribute wins too


# --- 8. connections the original drops ----------------------------------------------------
DROPPED = "err_dropped_connections.ikg"


def test_a_connection_to_nothing_is_an_error_by_default():
    with pytest.raises(ikaros.ModelError) as e:
        load(DROPPED)
    assert e.value.line == line_of(DROPPED, "MODULE") and "Nowhere.OUTPUT" in str(e.value)


def test_lenient_drops_connections_to_nothing_with_a_warning():
    net = load(DROPPED, lenient=True, quiet=True)
    found = warnings_of(net, DROPPED)
    assert sorted(found) == [line_of(DROPPED, m) for m in ("MODULE", "PORT", "TARGET")]
    assert all(m[0].endswith("; the connection is dropped (lenient)") for m in found.values())
    assert 'connection source "S.NOSUCH" not found' in found[line_of(DROPPED, "PORT")][0]
    net.run(ticks=2)
    same(net.output("K.OUTPUT"), [101])             # the one good connection, delay 1


def test_a_leniently_loaded_file_is_saved_without_the_dropped_connections(tmp_path):
    net = load(DROPPED, lenient=True, quiet=True)
    for helper in ("Seq.py", "Sink.py"):
        with open(model(helper)) as src, open(tmp_path / helper, "w") as dst:
            dst.write(src.read())
    net.save(str(tmp_path / "saved.ikg"))
    again = ikaros.load(str(tmp_path / "saved.ikg"), strict=True)
    assert again.warnings == []
    again.run(ticks=2)
    same(again.output("K.OUTPUT"), [101])


# --- 5. sizing as the original sizes; data blocks ---------------------------------------
def test_a_loop_of_modules_with_several_inputs_is_sized_and_runs():
    net = load("compat_sizes.ikg", quiet=True)
    for name in "ABC":
        assert net.output(f"{name}.OUTPUT").shape == (3,)
    z = [1, 2, 3]
    # by hand: tick 0: A=Z, B=Z, C=0; tick 1: A=Z, B=2Z, C=2Z; tick 2: A=3Z, B=2Z, C=3Z
    net.run(ticks=3)
    same(net.output("A.OUTPUT"), [3 * v for v in z])
    same(net.output("B.OUTPUT"), [2 * v for v in z])
    same(net.output("C.OUTPUT"), [3 * v for v in z])


def test_size_set_over_different_sizes_takes_the_largest_with_a_warning():
    net = load("compat_sizes.ikg", quiet=True)
    assert net.output("D.OUTPUT").shape == (3,)
    net.step()
    same(net.output("D.OUTPUT"), [16, 16, 16])
    (message,) = warnings_of(net, "compat_sizes.ikg")[line_of("compat_sizes.ikg", "DIFFERENT")]
    assert message == ('size_set="INPUT1,INPUT2": the inputs have different sizes ((3,), (1,)); '
                       'the largest, (3,), is used')


def test_size_and_shape_on_the_element():
    net = load("compat_sizes.ikg", quiet=True)
    assert net.output("R1.OUTPUT").shape == (4,)
    assert net.output("R2.OUTPUT").shape == (2, 3)


def test_data_blocks():
    net = load("compat_sizes.ikg", quiet=True)
    p = net.parameter
    assert (p("L1.p"), p("L2.p"), p("L3.p"), p("L4.p"), p("L5.p")) == (1, 2, 33, 32, 999)
    assert (p("L6.p"), p("L6.q")) == (2, 2)          # an element that is only data


# --- the editor saves clean files ---------------------------------------------------------
def test_the_editor_saves_a_leniently_loaded_file_clean(tmp_path):
    testclient = pytest.importorskip("starlette.testclient")
    from ikaros.webui.server import create_app
    for name in ("Seq.py", "Sink.py", "Par.py"):
        with open(model(name)) as src, open(tmp_path / name, "w") as dst:
            dst.write(src.read())
    text = open(model(DROPPED)).read().replace(
        '<module class="Sink" name="K"/>',
        '<module class="Par"p="4" p="5"/>\n    <module class="Sink" name="K"/>')
    (tmp_path / "m.ikg").write_text(text)
    net = ikaros.load(str(tmp_path / "m.ikg"), lenient=True, quiet=True)
    assert len(net.warnings) == 6       # glued, repeated, nameless, and three connections
    try:
        with testclient.TestClient(create_app(net)) as client:
            tree = client.get("/api/model").json()["tree"]
            assert client.post("/api/save", json={"tree": tree}).status_code == 200
    finally:
        net.close()
    again = ikaros.load(str(tmp_path / "m.ikg"), strict=True)
    assert again.warnings == [] and again.parameter("Par.p") == 4
    again.run(ticks=2)
    same(again.output("K.OUTPUT"), [101])


# --- forms of the Ikaros 3 kernel tests ---------------------------------------------------
def test_a_variable_holding_arithmetic_is_computed_where_it_is_defined():
    net = load("compat_rules.ikg", strict=True)
    assert net.parameter("Spliced.S.p") == 3000          # (1+2)*1000, not 1+2*1000
    same(net.parameter("Spliced.S.m"), [[1001, 4], [6, 30]])


def test_a_shape_expression_naming_a_string_parameter():
    net = load("compat_rules.ikg", strict=True)
    net.step()
    same(net.output("SL1.OUTPUT"), [[6, 6, 6], [6, 6, 6]])     # the class default "2,3"
    same(net.output("SL2.OUTPUT"), [4, 4, 4, 4])


def test_a_delay_window_into_a_target_selector():
    net = load("compat_window_selector.ikg", quiet=True)
    assert net.output("K.OUTPUT").shape == (2, 2)
    net.run(ticks=3)         # after tick 2, longest delay first (an Ikaros 2 file):
    same(net.output("K.OUTPUT"), [[101, 201], [102, 202]])     # [v(0), v(1)]
    same(net.output("L.OUTPUT"), [[202], [203]])               # [v(1)[1], v(2)[1]]
