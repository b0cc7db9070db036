"""Where classes are found, and that Python and .ikc declarations describe a class alike."""
import sys
import textwrap

import pytest

import ikaros
from ikaros.kernel import classes as class_finder

PY_CLASS = '''
from ikaros.module import Input, Module, Output, Parameter


class Twice(Module):
    """Doubles its input."""
    gain = Parameter(2.0, "the factor")
    mode = Parameter("fast", "how", options="fast,slow")
    INPUT = Input("in")
    AUX = Input("extra", optional=True)
    OUTPUT = Output("out", size_set="INPUT")

    def tick(self):
        self.OUTPUT[...] = self.gain * self.INPUT
'''

IKC_CLASS = '''<?xml version="1.0"?>
<class name="Twice" description="Doubles its input.">
    <parameter name="gain" type="float" default="2.0" description="the factor"/>
    <parameter name="mode" type="list" values="fast/slow" default="fast" description="how"/>
    <input name="INPUT" description="in"/>
    <input name="AUX" optional="yes" description="extra"/>
    <output name="OUTPUT" size_set="INPUT" description="out"/>
</class>
'''

IKC_CODE = '''
from ikaros.module import Module


class Twice(Module):
    def tick(self):
        self.OUTPUT[...] = self.gain * self.INPUT
'''

MODEL = '''<group name="M">
    <module class="Constant" name="C" data="1 2"/>
    <module class="Twice" name="T"/>
    <connection source="C.OUTPUT" target="T.INPUT" delay="0"/>
</group>
'''


def _strip(desc):
    d = desc.to_dict()
    d.pop("source")
    for p in d["parameters"]:
        p["default"] = str(p["default"]).replace("2.0", "2")
    return d


def test_python_and_ikc_declarations_give_the_same_description(tmp_path):
    (tmp_path / "py").mkdir()
    (tmp_path / "ikc").mkdir()
    (tmp_path / "py" / "Twice.py").write_text(PY_CLASS)
    (tmp_path / "ikc" / "Twice.ikc").write_text(IKC_CLASS)
    (tmp_path / "ikc" / "Twice.py").write_text(IKC_CODE)
    from_py = ikaros.classes(str(tmp_path / "py"))["Twice"]
    from_ikc = ikaros.classes(str(tmp_path / "ikc"))["Twice"]
    assert _strip(from_py) == _strip(from_ikc)
    for folder in ("py", "ikc"):
        (tmp_path / folder / "m.ikg").write_text(MODEL)
        net = ikaros.load(str(tmp_path / folder / "m.ikg"))
        net.step()
        assert net.output("T.OUTPUT").tolist() == [2, 4]
        assert net.parameter("T.mode") == "fast"


def test_ikc_without_code_is_a_class_that_does_nothing(tmp_path):
    (tmp_path / "Twice.ikc").write_text(IKC_CLASS)
    (tmp_path / "m.ikg").write_text(MODEL)
    net = ikaros.load(str(tmp_path / "m.ikg"))
    net.step()
    assert net.output("T.OUTPUT").tolist() == [0, 0]


def test_a_class_declared_twice_is_an_error(tmp_path):
    (tmp_path / "Twice.ikc").write_text(IKC_CLASS)
    (tmp_path / "Twice.py").write_text(PY_CLASS)
    (tmp_path / "m.ikg").write_text(MODEL)
    with pytest.raises(ikaros.ModelError, match="declared twice") as e:
        ikaros.load(str(tmp_path / "m.ikg"))
    assert e.value.line == 3


def test_path_attribute_is_searched_first(tmp_path):
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "Twice.py").write_text(PY_CLASS)
    (tmp_path / "m.ikg").write_text(MODEL.replace('class="Twice"', 'class="Twice" path="lib"'))
    net = ikaros.load(str(tmp_path / "m.ikg"))
    net.step()
    assert net.output("T.OUTPUT").tolist() == [2, 4]


def test_installed_package_entry_point(tmp_path, monkeypatch):
    pkg = tmp_path / "site" / "twicepkg"
    pkg.mkdir(parents=True)
    (pkg / "__init__.py").write_text(PY_CLASS)
    info = tmp_path / "site" / "twicepkg-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: twicepkg\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[ikaros.modules]\nTwice = twicepkg:Twice\n")
    monkeypatch.syspath_prepend(str(tmp_path / "site"))
    monkeypatch.setattr(class_finder, "_entry_point_cache", None)
    try:
        assert "Twice" in ikaros.classes()
        (tmp_path / "m.ikg").write_text(MODEL)
        net = ikaros.load(str(tmp_path / "m.ikg"))
        net.step()
        assert net.output("T.OUTPUT").tolist() == [2, 4]
    finally:
        class_finder._entry_point_cache = None
        sys.modules.pop("twicepkg", None)


def test_unknown_class_names_the_element(tmp_path):
    (tmp_path / "m.ikg").write_text(textwrap.dedent('''\
        <group name="M">

            <module class="NoSuch" name="X"/>
        </group>'''))
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(str(tmp_path / "m.ikg"))
    assert e.value.line == 3 and e.value.filename == str(tmp_path / "m.ikg")
    assert str(e.value) == f'{tmp_path / "m.ikg"}:3: <module name="X">: unknown class "NoSuch"'
