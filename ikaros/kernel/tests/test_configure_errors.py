"""How an exception raised in a module's configure() is reported: once, at the module element."""
import pytest

import ikaros
from ikaros.errors import ModelError

CLASS = '''
from ikaros.errors import ModelError
from ikaros.module import Module


class {name}(Module):
    """Test class: configure() raises {error}."""

    def configure(self):
        raise {error}
'''


def _load(tmp_path, module_element):
    (tmp_path / "Failing.py").write_text(CLASS.format(name="Failing",
                                                      error='ValueError("no such mode")'))
    (tmp_path / "FailingBare.py").write_text(CLASS.format(name="FailingBare",
                                                          error='ModelError("a bare model error")'))
    (tmp_path / "m.ikg").write_text(f"<group>\n    {module_element}\n</group>\n")
    with pytest.raises(ModelError) as caught:
        ikaros.load(str(tmp_path / "m.ikg"))
    return str(caught.value)


def test_a_model_error_that_names_its_place_is_reported_once(tmp_path):
    assert _load(tmp_path, '<module class="OutputRawImage" name="W" />') == \
        f'{tmp_path / "m.ikg"}:2: <module name="W">: OutputRawImage needs a filename'


def test_any_other_exception_is_located_at_the_module_element(tmp_path):
    assert _load(tmp_path, '<module class="Failing" name="F" />') == \
        f'{tmp_path / "m.ikg"}:2: <module name="F">: configure failed: ValueError: no such mode'


def test_a_model_error_without_a_place_is_located_at_the_module_element(tmp_path):
    assert _load(tmp_path, '<module class="FailingBare" name="F" />') == \
        (f'{tmp_path / "m.ikg"}:2: <module name="F">: configure failed: '
         "ModelError: a bare model error")
