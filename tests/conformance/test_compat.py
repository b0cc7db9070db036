"""Issue 11: what the original Ikaros accepts, this accepts (with a warning naming file and
line); ``strict=True`` makes each such warning an error."""
import os

import pytest

import ikaros
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
