"""Which Ikaros a model file is written for, from what it contains."""
from ikaros.language.dialect import detect_dialect, ikaros3_form
from ikaros.language.reader import read_file


def _read(tmp_path, text, name="m.ikg"):
    (tmp_path / name).write_text(text)
    return read_file(str(tmp_path / name))


def test_a_plain_file_is_ikaros_2(tmp_path):
    tree = _read(tmp_path, '<group name="G" stop="5" tick_duration="0.1" threads="2">'
                           '<module class="Constant" name="C" async="yes" start_tick="2"/>'
                           '<connection source="C.OUTPUT[0:1]" target="P.INPUT" delay="1:3"/>'
                           '</group>')
    assert ikaros3_form(tree) is None
    assert detect_dialect(tree) == "2"


def test_an_ikaros_3_form_in_an_included_file_counts(tmp_path):
    _read(tmp_path, '<widget class="plot" name="W"/>', name="views.ikg")
    tree = _read(tmp_path, '<group name="G"><group name="Inner"><?include file="views.ikg"?>'
                           '</group></group>')
    assert ikaros3_form(tree) == "a <widget> element"
    assert detect_dialect(tree) == "3"


def test_the_first_form_found_is_named(tmp_path):
    assert ikaros3_form(_read(tmp_path, '<group name="G" webui_port="8001"/>')) == \
        'the top-group setting "webui_port"'
    assert ikaros3_form(_read(tmp_path, '<group name="G"><connection source="A.OUTPUT" '
                                        'target="B.INPUT" delay=" [0:2]"/></group>')) == \
        'the bracketed delay " [0:2]"'
