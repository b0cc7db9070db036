"""The model file's Ikaros version (the top group's ``dialect``) as modules see it."""
import pytest

import ikaros
from ikaros.errors import ModelError

MODEL = """<group{attr}>
  <module class="Constant" name="C" data="1, 2"/>
  <module class="Scale" name="S" factor="2"/>
  <connection source="C.OUTPUT" target="S.INPUT"/>
</group>"""


def _dialects(tmp_path, attr):
    path = tmp_path / "m.ikg"
    path.write_text(MODEL.format(attr=attr))
    with ikaros.load(str(path)) as net:
        return sorted({inst.module.dialect for inst in net.modules.values()})


def test_a_file_without_a_dialect_is_ikaros_2(tmp_path):
    assert _dialects(tmp_path, "") == ["2"]


def test_the_top_group_names_the_dialect(tmp_path):
    assert _dialects(tmp_path, ' dialect="3"') == ["3"]


def test_an_unknown_dialect_is_refused_naming_the_file(tmp_path):
    with pytest.raises(ModelError, match=r'm\.ikg:1: .*dialect="4" must be "2"'):
        _dialects(tmp_path, ' dialect="4"')
