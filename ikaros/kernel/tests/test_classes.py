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


def test_ikc_without_code_is_an_error_not_a_do_nothing_class(tmp_path):
    (tmp_path / "Twice.ikc").write_text(IKC_CLASS)
    (tmp_path / "m.ikg").write_text(MODEL)
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(str(tmp_path / "m.ikg"))
    assert e.value.line == 3 and e.value.filename == str(tmp_path / "m.ikg")
    assert e.value.reason.startswith("class Twice is declared in Twice.ikc but has no "
                                     "implementation")


def test_a_script_beside_an_ikc_is_not_its_implementation(tmp_path):
    (tmp_path / "Twice.ikc").write_text(IKC_CLASS)
    (tmp_path / "Twice.py").write_text("raise SystemExit('a script for another program')\n")
    (tmp_path / "m.ikg").write_text(MODEL)
    with pytest.raises(ikaros.ModelError, match="has no implementation"):
        ikaros.load(str(tmp_path / "m.ikg"))


def test_an_ikaros3_python_script_class_runs_its_script(tmp_path):
    """python="twice.py" on the class: the script runs in a worker (docs/python-scripts.md),
    with the .ikc's parameters and the scripted-class settings."""
    (tmp_path / "Twice.ikc").write_text(IKC_CLASS.replace('<class name="Twice"',
                                                          '<class name="Twice" python="twice.py"'))
    (tmp_path / "twice.py").write_text("def tick(module):\n"
                                       "    return {'OUTPUT': module.gain * module.INPUT}\n")
    (tmp_path / "m.ikg").write_text(MODEL)
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        net.step()
        assert net.output("T.OUTPUT").tolist() == [2, 4]
        assert net.parameter("T.on_error") == "fail"
    desc = ikaros.classes(str(tmp_path))["Twice"]
    assert [p.name for p in desc.parameters] == ["gain", "mode", "on_error", "restart_on_crash",
                                                 "use_global_names", "python_executable"]


def test_a_script_beside_an_ikc_with_a_tick_function_is_its_script(tmp_path):
    """Ikaros 3 finds <Class>.py beside the .ikc: one that defines tick() and is no module
    of this project's API is the class's script."""
    (tmp_path / "Twice.ikc").write_text(IKC_CLASS)
    (tmp_path / "Twice.py").write_text("def tick(module):\n"
                                       "    module.OUTPUT[:] = 3 * module.INPUT\n")
    (tmp_path / "m.ikg").write_text(MODEL)
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        net.step()
        assert net.output("T.OUTPUT").tolist() == [3, 6]


SCALE_IKC = '''<class name="Scale">
    <parameter name="factor" type="float" default="1"/>
    <input name="INPUT"/>
    <output name="OUTPUT" size_set="INPUT"/>
</class>
'''

SCALE_MODEL = '''<group name="M">
    <module class="Constant" name="C" data="1 2"/>
    <module class="Scale" name="S" factor="3"/>
    <connection source="C.OUTPUT" target="S.INPUT" delay="0"/>
</group>
'''


def test_an_ikc_of_a_standard_class_runs_the_standard_implementation(tmp_path):
    (tmp_path / "Scale.ikc").write_text(SCALE_IKC)
    (tmp_path / "m.ikg").write_text(SCALE_MODEL)
    net = ikaros.load(str(tmp_path / "m.ikg"), quiet=True)
    net.step()
    assert net.output("S.OUTPUT").tolist() == [3, 6]
    assert net.warnings == []


def test_an_ikc_parameter_the_implementation_lacks_is_a_warning(tmp_path):
    ikc = SCALE_IKC.replace("<input", '<parameter name="offset" default="2"/>\n    <input')
    (tmp_path / "Scale.ikc").write_text(ikc)
    (tmp_path / "m.ikg").write_text(SCALE_MODEL)
    net = ikaros.load(str(tmp_path / "m.ikg"), quiet=True)
    net.step()
    assert net.output("S.OUTPUT").tolist() == [3, 6]
    (w,) = net.warnings
    assert (w.filename, w.line, w.element) == (str(tmp_path / "Scale.ikc"), 3,
                                               '<parameter name="offset">')
    assert w.message.endswith('has no parameter "offset"; ignored')
    with pytest.raises(ikaros.ModelError, match="offset"):
        ikaros.load(str(tmp_path / "m.ikg"), strict=True)


def test_an_ikc_output_the_implementation_lacks_is_an_error(tmp_path):
    ikc = SCALE_IKC.replace("</class>", '    <output name="GAIN" size="1"/>\n</class>')
    (tmp_path / "Scale.ikc").write_text(ikc)
    (tmp_path / "m.ikg").write_text(SCALE_MODEL)
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(str(tmp_path / "m.ikg"))
    assert (e.value.filename, e.value.line) == (str(tmp_path / "m.ikg"), 3)
    assert f'{tmp_path / "Scale.ikc"}:5: <output name="GAIN">: ' in str(e.value)
    assert str(e.value).endswith('has no output "GAIN"')


def test_a_script_named_like_a_standard_class_does_not_hide_it(tmp_path):
    (tmp_path / "Scale.py").write_text("class Scale(object):\n    pass\n\n"
                                       "raise SystemExit('a script for another program')\n")
    (tmp_path / "m.ikg").write_text(SCALE_MODEL)
    net = ikaros.load(str(tmp_path / "m.ikg"))
    net.step()
    assert net.output("S.OUTPUT").tolist() == [3, 6]


def test_a_broken_python_file_beside_a_model_is_left_out_of_the_class_list(tmp_path, capsys):
    (tmp_path / "Plot.py").write_text("import no_such_package\nfrom ikaros.module import "
                                      "Module\n\n\nclass Plot(Module):\n    pass\n")
    (tmp_path / "Chart.py").write_text("class Chart(object):\n    pass\n")   # not a module
    (tmp_path / "Twice.py").write_text(PY_CLASS)
    found = ikaros.classes(str(tmp_path))
    assert "Twice" in found and "Plot" not in found and "Chart" not in found
    assert "Plot.py" in capsys.readouterr().err


def test_a_python_file_that_is_not_utf_8_is_read_as_python_reads_it(tmp_path):
    latin = PY_CLASS.replace('"""Doubles its input."""', '"""Doubles its input (d\xe9j\xe0)."""')
    (tmp_path / "Twice.py").write_bytes(b"# -*- coding: latin-1 -*-\n" + latin.encode("latin-1"))
    (tmp_path / "m.ikg").write_text(MODEL)
    net = ikaros.load(str(tmp_path / "m.ikg"))          # its coding declaration is read
    net.step()
    assert net.output("T.OUTPUT").tolist() == [2, 4]
    assert ikaros.classes(str(tmp_path))["Twice"].description.endswith("(d\xe9j\xe0).")
    other = tmp_path / "undeclared"
    other.mkdir()
    (other / "Twice.py").write_bytes(latin.encode("latin-1"))      # no declaration
    (other / "m.ikg").write_text(MODEL)
    with pytest.raises(ikaros.ModelError) as e:     # (Python cannot import it either)
        ikaros.load(str(other / "m.ikg"))
    assert f'class "Twice": {other / "Twice.py"}: cannot import: SyntaxError: (unicode ' \
           f"error) 'utf-8' codec can't decode byte 0xe9" in str(e.value)


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


def test_a_python_class_and_a_group_file_of_one_name_in_one_folder_are_an_error(tmp_path):
    (tmp_path / "Twice.py").write_text(PY_CLASS)
    (tmp_path / "Twice.ikg").write_text('<group name="Twice"/>')
    model = tmp_path / "m.ikg"
    model.write_text('<group><module class="Twice" name="T"/></group>')
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(str(model))
    assert e.value.reason == (f'class "Twice" is declared by two class files in one folder: '
                              f'{tmp_path / "Twice.py"} and {tmp_path / "Twice.ikg"}; keep one')


TEST_ONLY = ("KernelTestModule", "DelaySequenceSource", "FirstTickReporter",
             "PersistentStateTestModule", "AsyncLifecycleTestModule",
             "MatrixFunctionTestModule", "DynamicMatrixSource", "SumInput")


def test_the_test_only_classes_are_found_by_name_without_a_path(tmp_path):
    # The original's kernel-test files name them like any class (issue 26, part 2).
    (tmp_path / "m.ikg").write_text(
        '<group name="T"><module class="DelaySequenceSource" name="S" offset="5"/>'
        '</group>')
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        net.run(ticks=3)
        # tick 3 + offset: the test-only classes are Ikaros 3's, so the file is an Ikaros 3
        # file, whose first tick is 1
        assert net.output("S.OUTPUT").tolist() == [3 + 5]
    registry = class_finder.ClassRegistry([str(tmp_path)])
    for name in TEST_ONLY:
        assert registry.find(name) is not None, name


def test_the_test_only_classes_are_listed_nowhere(tmp_path):
    listed = set(class_finder.classes([str(tmp_path)]))      # --classes and /api/classes
    from ikaros.docgen import standard_classes
    documented = set(standard_classes())                     # docs/modules.md
    for name in TEST_ONLY:
        assert name not in listed and name not in documented, name


def test_a_class_beside_the_model_wins_over_a_test_only_class_of_that_name(tmp_path):
    (tmp_path / "FirstTickReporter.py").write_text(PY_CLASS.replace("Twice", "FirstTickReporter"))
    entry = class_finder.ClassRegistry([str(tmp_path)]).find("FirstTickReporter")
    assert entry.python == str(tmp_path / "FirstTickReporter.py")
