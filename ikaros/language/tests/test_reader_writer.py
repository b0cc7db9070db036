import pytest

from ikaros.language.diagnostics import Diagnostics, collecting

from ikaros.errors import ModelError
from ikaros.language.node import INCLUDE
from ikaros.language.reader import read_file
from ikaros.language.writer import to_text

MODEL = """<?xml version="1.0"?>
<group name="G" a="1">
    <!-- a comment -->
    <module class="Constant" name="C" data="1 2" _x="10" unknown="kept"/>
    <?include file="part.ikg"?>
    <view name="V"><plot source="C.OUTPUT" x="1"/></view>
</group>
"""

PART = """<module class="Scale" name="S"/>
<connection source="C.OUTPUT" target="S.INPUT"/>
"""


def test_lines_files_and_includes(tmp_path):
    (tmp_path / "part.ikg").write_text(PART)
    root = read_file(str(tmp_path / "m.ikg"), MODEL)
    assert root.tag == "group" and root.line == 2 and root.attrs == {"name": "G", "a": "1"}
    tags = [n.tag for n in root.elements()]
    assert tags == ["module", "module", "connection", "view"]
    scale = list(root.elements("module"))[1]
    assert scale.file == str(tmp_path / "part.ikg") and scale.line == 1
    assert list(root.elements("connection"))[0].line == 2
    assert any(c.tag == INCLUDE for c in root.children)


def test_writer_keeps_attributes_comments_and_includes(tmp_path):
    (tmp_path / "part.ikg").write_text(PART)
    root = read_file(str(tmp_path / "m.ikg"), MODEL)
    text = to_text(root)
    assert '<module class="Constant" name="C" data="1 2" _x="10" unknown="kept"/>' in text
    assert "<!-- a comment -->" in text
    assert '<?include file="part.ikg"?>' in text
    assert 'class="Scale"' not in text        # the include is written, not its contents
    again = read_file(str(tmp_path / "m.ikg"), text)
    assert [n.attrs for n in again.elements()] == [n.attrs for n in root.elements()]


def test_malformed_xml_names_file_and_line(tmp_path):
    with pytest.raises(ModelError) as e:
        read_file(str(tmp_path / "bad.ikg"), '<group name="G">\n  <module name="A"\n</group>')
    assert e.value.filename == str(tmp_path / "bad.ikg")
    assert e.value.line == 3
    assert "malformed XML" in str(e.value)


def test_include_errors(tmp_path):
    with pytest.raises(ModelError, match='included file "missing.ikg" not found') as e:
        read_file(str(tmp_path / "m.ikg"), '<group>\n<?include file="missing.ikg"?>\n</group>')
    assert e.value.line == 2
    (tmp_path / "self.ikg").write_text('<?include file="self.ikg"?>')
    with pytest.raises(ModelError, match="includes itself"):
        read_file(str(tmp_path / "m.ikg"), '<group><?include file="self.ikg"?></group>')


def test_includes_nested_too_deep_are_told_once_where_they_are_with_the_chain(tmp_path):
    for k in range(40):             # i0 includes i1 includes ... i40
        (tmp_path / f"i{k}.ikg").write_text(f'\n<?include file="i{k + 1}.ikg"?>\n')
    (tmp_path / "i40.ikg").write_text('<module class="Constant" name="C"/>')
    with pytest.raises(ModelError) as e:
        read_file(str(tmp_path / "m.ikg"), '<group><?include file="i0.ikg"?></group>')
    chain = " > ".join(["m.ikg"] + [f"i{k}.ikg" for k in range(31)])
    assert str(e.value) == (f"{tmp_path}/i30.ikg:2: includes nest deeper than 32 levels "
                            f"(through {chain})")
    (tmp_path / "i3.ikg").write_text('<?include file="notes.txt"?>')
    (tmp_path / "notes.txt").write_text("not a model")
    with pytest.raises(ModelError) as e:
        read_file(str(tmp_path / "m.ikg"), '<group><?include file="i0.ikg"?></group>')
    assert str(e.value) == (f'{tmp_path}/i3.ikg:1: included file "notes.txt" is not model '
                            f'text (through m.ikg > i0.ikg > i1.ikg > i2.ikg > i3.ikg): '
                            f'{tmp_path}/notes.txt:1: text outside the elements: "not a '
                            f'model"')


def test_root_must_be_the_expected_kind(tmp_path):
    with pytest.raises(ModelError, match="must be <group>") as e:
        read_file(str(tmp_path / "m.ikg"), "<class name='X'/>", root_tag="group")
    assert e.value.line == 1


def test_comments_around_the_root_are_kept(tmp_path):
    text = ('<?xml version="1.0"?>\n<!-- before -->\n<!-- also before -->\n'
            '<group name="G"/>\n<!-- after -->\n')
    root = read_file(str(tmp_path / "m.ikg"), text)
    assert root.outside == ([" before ", " also before "], [" after "])
    written = to_text(root)
    assert written == ('<?xml version="1.0"?>\n<!-- before -->\n<!-- also before -->\n'
                       '<group name="G"/>\n<!-- after -->\n')
    assert root.copy().outside == root.outside


def test_entities_are_never_expanded(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("private")
    text = ('<?xml version="1.0"?>\n<!DOCTYPE g [\n <!ENTITY lol "lol">\n'
            f' <!ENTITY xxe SYSTEM "file://{secret}">\n]>\n<group name="&lol;" a="&xxe;"/>\n')
    diagnostics = Diagnostics(quiet=True)
    with collecting(diagnostics):
        root = read_file(str(tmp_path / "m.ikg"), text)
    assert root.attrs == {"name": "&lol;", "a": "&xxe;"}     # kept as written (Ikaros 2)
    assert [w.line for w in diagnostics.warnings] == [6]
    with pytest.raises(ModelError, match="bare &") as e:
        with collecting(Diagnostics(strict=True)):
            read_file(str(tmp_path / "m.ikg"), text)
    assert e.value.line == 6
    root = read_file(str(tmp_path / "m.ikg"), '<group name="a&amp;b&#65;"/>')
    assert root.attrs["name"] == "a&bA"          # XML's own entities and references


def test_an_element_keeps_its_text_before_the_first_child(tmp_path):
    root = read_file(str(tmp_path / "m.ikg"),
                     '<group><note> A <b>free</b> text</note><d>\n  plain\n</d></group>')
    note, d = root.children
    assert (note.text, note.children[0].text, d.text) == ("A", "free", "plain")
