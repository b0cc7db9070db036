"""Which Ikaros a model file is written for, from what it contains."""
import glob
import json
import os

import pytest

import ikaros
from ikaros.language.dialect import detect_dialect, ikaros3_form, read_dialect
from ikaros.language.reader import read_file

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))


def _read(tmp_path, text, name="m.ikg"):
    (tmp_path / name).write_text(text)
    return read_file(str(tmp_path / name))


def _reading(tmp_path, body, top=""):
    tree = _read(tmp_path, f'<group name="G"{top}>{body}</group>')
    return read_dialect(tree, str(tmp_path))


def test_a_file_with_no_sign_is_ikaros_2(tmp_path):
    reading = _reading(tmp_path, '<module class="Constant" name="C" data="1, 2"/>'
                                 '<module class="Scale" name="S" async="yes" start_tick="2"/>'
                                 '<connection source="C.OUTPUT[0:1]" target="S.INPUT" '
                                 'delay="1:3"/>')
    assert reading.dialect == "2" and reading.reason is None


def test_an_ikaros_3_form_in_an_included_file_counts(tmp_path):
    _read(tmp_path, '<widget class="plot" name="W"/>', name="views.ikg")
    tree = _read(tmp_path, '<group name="G"><group name="Inner"><?include file="views.ikg"?>'
                           '</group></group>')
    assert ikaros3_form(tree) == "a <widget> element"
    assert detect_dialect(tree) == "3"
    assert read_dialect(tree).reason is None       # a form only Ikaros 3 reads: no doubt


def test_the_first_form_found_is_named(tmp_path):
    assert ikaros3_form(_read(tmp_path, '<group name="G" webui_port="8001"/>')) == \
        'the top-group setting "webui_port"'
    assert ikaros3_form(_read(tmp_path, '<group name="G"><connection source="A.OUTPUT" '
                                        'target="B.INPUT" delay=" [0:2]"/></group>')) == \
        'the bracketed delay " [0:2]"'


@pytest.mark.parametrize("body, top, sign", [
    ('<module class="Print" name="P"/>', "", 'the class "Print"'),
    ('<module class="Randomizer" name="R" seed="3"/>', "", 'the parameter "seed" of Randomizer'),
    ('<module class="FunctionGenerator" name="F" type="sine"/>', "",
     'type="sine" of FunctionGenerator'),
    ('<module class="Constant" name="C"/><module class="Max" name="M"/>'
     '<connection source="C.OUTPUT" target="M.INPUT"/>', "", "the port INPUT of Max"),
    ('<group name="In"><input name="X"/><module class="Scale" name="S"/>'
     '<connection source="X" target="S.INPUT"/></group>', "",
     'the group input "X" without target='),
    ('<module class="Constant" name="C"/><module class="Scale" name="S"/>'
     '<connection source="C.OUTPUT" target="S.INPUT" label="speed"/>', "",
     "a connection label"),
    ('<module class="Scale" name="S" INPUT.flatten="yes"/>', "",
     'the input flag "INPUT.flatten"'),
    ('<module class="Constant" name="C"/>', ' stop="10"', 'the top-group setting "stop"'),
])
def test_a_sign_of_ikaros_3_alone_makes_an_ikaros_3_file_and_says_so(tmp_path, body, top,
                                                                     sign):
    reading = _reading(tmp_path, body, top)
    assert reading.dialect == "3"
    assert reading.reason.startswith(f"read as an Ikaros 3 file: {sign} (line ")
    assert reading.reason.endswith('write dialect="2" on the top group to read it as Ikaros 2')


@pytest.mark.parametrize("body", [
    '<module class="Sweep" name="S"/>',                                    # a class of Ikaros 2
    '<module class="Constant" name="C" data="1 2 3"/>',                    # spaces in a matrix
    '<group name="In"><input name="X" target="S.INPUT"/><module class="Scale" name="S"/>'
    '</group>',                                                            # an alias
    '<module class="Constant" name="C"/><module class="Scale" name="S"/>'
    '<connection source="C.OUTPUT" target="S.INPUT" sourceoffset="0" size="1"/>',
    '<module class="Constant" name="C"/><module class="Scale" name="S"/>'
    '<connection source="C.OUTPUT" target="S.INPUT" delay="1,3"/>',        # a delay list
    '<view name="V"/>',
    '<module class="Constant" name="C"/><module class="Max" name="M"/>'
    '<connection source="C.OUTPUT" target="M.INPUT1"/>',                   # Ikaros 2's port
])
def test_a_sign_of_ikaros_2_outweighs_the_weak_signs_of_ikaros_3(tmp_path, body):
    # the parameters and settings of Ikaros 3 that this project's Ikaros 2 files use too
    reading = _reading(tmp_path, body + '<module class="Randomizer" name="R" seed="1"/>',
                       ' stop="10" tick_duration="0.1"')
    assert reading == read_dialect(read_file(str(tmp_path / "m.ikg"))) and \
        reading.dialect == "2" and reading.reason is None


def test_strong_signs_of_both_give_ikaros_2_and_say_why(tmp_path):
    reading = _reading(tmp_path, '<module class="Sweep" name="S"/>\n'
                                 '<module class="Print" name="P"/>')
    assert reading.dialect == "2"
    assert reading.reason == (
        'read as an Ikaros 2 file: the class "Sweep" (line 1) is Ikaros 2\'s, although the '
        'class "Print" (line 2) is Ikaros 3\'s; write dialect="3" on the top group to read it '
        'as Ikaros 3')


def test_a_class_file_of_ikaros_3_beside_the_model_is_a_sign(tmp_path):
    (tmp_path / "Gain.ikc").write_text(
        '<class name="Gain"><parameter name="k" type="number" default="1"/>'
        '<input name="INPUT"/><output name="OUTPUT" shape="INPUT.shape"/></class>')
    (tmp_path / "Old.ikc").write_text(
        '<class name="Old"><parameter name="k" type="float" default="1"/>'
        '<input name="INPUT"/><output name="OUTPUT" size_set="INPUT"/></class>')
    body = '<module class="Old" name="O"/>'
    assert _reading(tmp_path, body).dialect == "2"
    reading = _reading(tmp_path, body + '<module class="Gain" name="G"/>')
    assert reading.dialect == "3"
    assert 'the Ikaros 3 class file "Gain.ikc" beside it' in reading.reason
    # without the folder (a tree read from text), the class files are not looked at
    assert read_dialect(read_file(str(tmp_path / "m.ikg"))).dialect == "2"


def test_the_loader_prints_the_reason_as_a_note_that_strict_does_not_refuse(tmp_path, capsys):
    (tmp_path / "m.ikg").write_text('<group name="G">\n<module class="Constant" name="C"/>\n'
                                    '<module class="Print" name="P"/>\n'
                                    '<connection source="C.OUTPUT" target="P.INPUT"/></group>')
    with ikaros.load(str(tmp_path / "m.ikg"), strict=True) as net:
        assert net.dialect == "3" and net.first_tick == 1
        assert net.warnings == []
        [note] = net.diagnostics.notes
        assert (note.filename, note.line) == (str(tmp_path / "m.ikg"), 1)
    err = capsys.readouterr().err
    assert f"{tmp_path / 'm.ikg'}:1: note: read as an Ikaros 3 file: the class \"Print\" " \
           f"(line 3) is Ikaros 3's" in err
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True, dialect=2) as net:
        assert net.dialect == "2" and net.diagnostics.notes == []
    assert capsys.readouterr().err == ""


def test_every_ikaros_2_golden_model_is_read_as_ikaros_2():
    files = glob.glob(os.path.join(ROOT, "tests", "golden", "files-v2", "*.json"))
    assert files
    for file in files:
        with open(file, encoding="utf-8") as f:
            golden = json.load(f)
        for case in golden["cases"]:
            tree = read_file("golden.ikg", case["model"], root_tag="group")
            assert detect_dialect(tree) == "2", (golden["class"], case["name"])
