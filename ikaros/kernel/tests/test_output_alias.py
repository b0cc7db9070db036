"""Output aliases (Ikaros 3 ``alias="OUTPUT[1]"``): views of another output of the module."""
import numpy as np
import pytest

import ikaros
from ikaros import Input, Module, Output
from ikaros.errors import ModelError
from ikaros.language.classfile import read_class_file


class Rows(Module):
    """OUTPUT = INPUT * 10; SECOND views its second row, LAST its last element."""
    INPUT = Input("a matrix")
    OUTPUT = Output("INPUT * 10", shape="INPUT.shape")
    SECOND = Output("row 1", alias="OUTPUT[1]")
    LAST = Output("the last element", alias="OUTPUT[1][1]")

    def tick(self):
        self.OUTPUT[...] = self.INPUT * 10


def _build(tmp_path, body, classes=None):
    model = tmp_path / "m.ikg"
    model.write_text(f"<group>{body}</group>")
    return ikaros.build_tree(None, str(model), classes=classes or {"Rows": Rows})


SOURCE = '<module class="Constant" name="C" data="1 2; 3 4"/>' \
         '<connection source="C.OUTPUT" target="R.INPUT" delay="0"/>'


def test_an_alias_views_the_memory_of_its_output(tmp_path):
    net = _build(tmp_path, SOURCE + '<module class="Rows" name="R"/>')
    try:
        net.run(ticks=1)
        assert net.output("R.SECOND").tolist() == [30, 40]
        assert net.output("R.LAST").tolist() == [40]
        module = net.modules["R"].module
        assert np.shares_memory(module.SECOND, module.OUTPUT)
    finally:
        net.close()


@pytest.mark.parametrize("alias, message", [
    ("OUTPUT[0:1]", 'alias "OUTPUT[0:1]" must name another output of the module, with '
                    'single indices only (OUTPUT or OUTPUT[0])'),
    ("OUTPUT", None),
])
def test_an_alias_is_an_output_name_with_single_indices_and_no_shape(alias, message):
    if message:
        with pytest.raises(TypeError, match=r"single indices only"):
            Output("x", alias=alias)
    with pytest.raises(TypeError, match="can not also have a shape"):
        Output("x", alias=alias if message is None else "OUTPUT", shape="3")


@pytest.mark.parametrize("alias, message", [
    ("NONE", 'output "BAD" of R: alias "NONE" names no other output of the module'),
    ("OUTPUT[2]", 'output "BAD" of R: alias "OUTPUT[2]" is outside the shape [2, 2] of '
                  'OUTPUT'),
    ("OUTPUT[0][0][0]", 'output "BAD" of R: alias "OUTPUT[0][0][0]" is outside the shape '
                        '[2, 2] of OUTPUT'),
])
def test_an_alias_of_no_output_or_outside_it_is_an_error_at_the_module(tmp_path, alias,
                                                                          message):
    class Bad(Rows):
        BAD = Output("wrong", alias=alias)
    with pytest.raises(ModelError) as e:
        _build(tmp_path, SOURCE + '<module class="Bad" name="R"/>', {"Bad": Bad})
    assert e.value.reason == message and e.value.line == 1


def test_an_ikc_output_alias_with_a_size_is_an_error_naming_the_element(tmp_path):
    (tmp_path / "Rows.ikc").write_text(
        '<class name="Rows">\n<input name="INPUT"/>\n<output name="OUTPUT" shape="INPUT.shape"/>'
        '\n<output name="SECOND" alias="OUTPUT[1]" size="2"/>\n</class>')
    with pytest.raises(ModelError) as e:
        read_class_file(str(tmp_path / "Rows.ikc"))
    assert e.value.line == 4 and e.value.reason.startswith(
        'output "SECOND": an alias takes its shape from the output it views')
