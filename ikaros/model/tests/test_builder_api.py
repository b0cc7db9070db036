"""The builder API: models made in code are built, checked and saved as files are."""
import inspect

import numpy as np
import pytest

import ikaros


def here() -> int:
    """The line of the caller."""
    return inspect.currentframe().f_back.f_lineno


class Doubler(ikaros.Module):
    """Twice its input."""
    INPUT = ikaros.Input("a signal")
    OUTPUT = ikaros.Output("twice the signal", size_set="INPUT")

    def tick(self):
        self.OUTPUT[...] = 2 * self.INPUT


def test_a_model_in_code_runs_with_parameters_variables_and_delays():
    model = ikaros.Group("Arm", tick_duration=0.01, gain=3)
    ramp = model.module("Sweep", "Ramp", min=0, max=10, step=1)
    scale = model.module("Scale", "Gain", factor="@gain")
    model.connect(ramp.OUTPUT, scale.INPUT, delay=2)
    net = model.build()
    net.run(ticks=4)
    # the ramp gives 0 in init, then 1, 2, 3, 4 in ticks 0..3: two ticks late, times 3
    assert net.output("Gain.OUTPUT").tolist() == [6.0]
    assert net.clock.tick_duration == 0.01


def test_a_module_class_given_directly():
    model = ikaros.Group("M")
    source = model.module("Constant", "C", data="1, 2, 3")
    double = model.module(Doubler, "D")
    model.connect(source.OUTPUT, double.INPUT, delay=0)
    net = model.build()
    net.step()
    assert net.output("D.OUTPUT").tolist() == [2.0, 4.0, 6.0]
    assert 'class="Doubler"' in model.to_xml()


def test_selectors_offsets_and_delay_ranges():
    model = ikaros.Group("M")
    c = model.module("Constant", "C", data="1, 2, 3, 4")
    picked = model.module("Scale", "Picked", factor=1)
    placed = model.module("Scale", "Placed", factor=1)
    history = model.module("Scale", "History", factor=1)
    model.connect(c.OUTPUT[1:3], picked.INPUT, delay=0)
    model.connect(c.OUTPUT, placed.INPUT, delay=0, source_offset=2, size=2)
    model.connect(c.OUTPUT[0], history.INPUT, delay=range(0, 3))
    net = model.build()
    net.step()
    assert net.output("Picked.OUTPUT").tolist() == [2.0, 3.0]
    assert net.output("Placed.OUTPUT").tolist() == [3.0, 4.0]
    assert net.output("History.OUTPUT").shape == (3, 1)
    xml = model.to_xml()
    assert 'source="C.OUTPUT[1:3]"' in xml and 'delay="0, 1, 2"' in xml
    assert 'sourceoffset="2"' in xml and 'size="2"' in xml


def test_delay_forms_are_written_in_the_language():
    model = ikaros.Group("M")
    a, b = model.module("Constant", "A", data=1), model.module("Scale", "B")
    texts = [model.connect(a.OUTPUT, b.INPUT, delay=d).get("delay")
             for d in (1, range(1, 4), range(0, 6, 2), [0, 2], "2:4", None)]
    # a range is a list, which Ikaros 2 and Ikaros 3 files read alike
    assert texts == ["1", "1, 2, 3", "0, 2, 4", "0, 2", "2:4", None]
    net = model.build()
    assert net.dialect == "2"       # the model holds no Ikaros 3-only form: Ikaros 2's ticks
    # an Ikaros 2 file gives a window's slots longest delay first
    assert [r.delay for r in net.runs] == [1, 3, 2, 1, 4, 2, 0, 2, 0, 4, 3, 2, 1]


def test_nested_groups_with_inputs_and_outputs_and_parameters():
    model = ikaros.Group("Top")
    c = model.module("Constant", "C", data="5")
    inner = model.group("Inner", factor=4)
    scale = inner.module("Scale", "S", factor="@factor")
    inner.input("IN", target=scale.INPUT)
    inner.output("OUT", source=scale.OUTPUT)
    inner.parameter("factor", default=7)
    sink = model.module("Scale", "Sink", factor=1)
    model.connect(c.OUTPUT, inner.IN, delay=0)
    model.connect(inner.OUT, sink.INPUT, delay=0)
    net = model.build()
    net.step()
    assert net.output("Sink.OUTPUT").tolist() == [20.0]
    assert model["Inner.S"].class_name == "Scale"
    assert scale.path() == "Inner.S"


def test_a_port_of_a_nested_module_is_named_from_the_connecting_group():
    model = ikaros.Group("Top")
    inner = model.group("Inner")
    c = inner.module("Constant", "C", data="2")
    s = model.module("Scale", "S", factor=1)
    connection = model.connect(c.OUTPUT, s.INPUT, delay=0)
    assert connection.get("source") == "Inner.C.OUTPUT"
    net = model.build()
    net.step()
    assert net.output("S.OUTPUT").tolist() == [2.0]


def test_views_with_widgets():
    model = ikaros.Group("M")
    c = model.module("Constant", "C", data="1")
    view = model.view("Main")
    plot = view.widget("plot", source=c.OUTPUT, x=10, y=20, width=300, height=200)
    assert plot.get("source") == "C.OUTPUT" and plot.get("width") == "300"
    net = model.build()
    assert net.top.views[0].get("name") == "Main"


def test_an_error_names_the_python_line_of_the_element():
    model = ikaros.Group("M")
    model.module("Constant", "C", data="1")
    line = here() + 1
    model.module("NoSuchClass", "X")
    with pytest.raises(ikaros.ModelError) as e:
        model.build()
    assert e.value.filename == __file__ and e.value.line == line
    assert 'unknown class "NoSuchClass"' in str(e.value)
    assert f'{__file__}:{line}: <module name="X">' in str(e.value)


def test_a_bad_connection_names_the_line_of_connect():
    model = ikaros.Group("M")
    c = model.module("Constant", "C", data="1")
    s = model.module("Scale", "S")
    line = here() + 1
    model.connect(c.OUTPUT, s.NOPE)
    with pytest.raises(ikaros.ModelError) as e:
        model.build()
    assert e.value.line == line and "no input named \"NOPE\"" in str(e.value)


def test_a_bad_parameter_names_the_line():
    model = ikaros.Group("M")
    line = here() + 1
    model.module("Scale", "S", factor="lots")
    with pytest.raises(ikaros.ModelError) as e:
        model.build()
    assert e.value.line == line and e.value.filename == __file__


def test_read_change_save_and_load(tmp_path):
    path = tmp_path / "a.ikg"
    model = ikaros.Group("A", gain=2)
    c = model.module("Constant", "C", data="1, 2")
    s = model.module("Scale", "S", factor="@gain")
    model.connect(c.OUTPUT, s.INPUT, delay=0)
    model.save(str(path))
    read = ikaros.Group.read(str(path))
    assert read.filename == str(path)
    read["S"].set(factor=10)
    read.save(str(path))
    net = ikaros.load(str(path))
    net.step()
    assert net.output("S.OUTPUT").tolist() == [10.0, 20.0]
    assert path.read_text() == (
        '<?xml version="1.0"?>\n<group name="A" gain="2">\n'
        '    <module class="Constant" name="C" data="1, 2"/>\n'
        '    <module class="Scale" name="S" factor="10"/>\n'
        '    <connection source="C.OUTPUT" target="S.INPUT" delay="0"/>\n</group>\n')


def test_remove_takes_the_connections_of_a_module_along():
    model = ikaros.Group("M")
    c = model.module("Constant", "C", data="1")
    s = model.module("Scale", "S")
    model.connect(c.OUTPUT, s.INPUT)
    model.remove("S")
    assert model.connections == [] and [m.name for m in model.modules] == ["C"]
    assert model.disconnect(c.OUTPUT, "S.INPUT") == 0


def test_build_takes_overrides_and_warnings_settings():
    model = ikaros.Group("M", gain=2)
    c = model.module("Constant", "C", data="1")
    s = model.module("Scale", "S", factor="@gain")
    model.connect(c.OUTPUT, s.INPUT, delay=0)
    net = model.build(gain=5)
    net.step()
    assert net.output("S.OUTPUT").tolist() == [5.0]
    assert np.isclose(net.clock.tick_duration, 0.01)


def test_selectors_must_be_whole_numbers_or_ranges():
    model = ikaros.Group("M")
    c = model.module("Constant", "C", data="1")
    assert c.OUTPUT[1:3, 0].selector == "[1:3][0]"
    assert c.OUTPUT[:].selector == "[]"
    with pytest.raises(TypeError):
        c.OUTPUT["a"]
    with pytest.raises(ValueError):
        c.OUTPUT[1:]


def test_connecting_a_port_from_outside_the_group_names_the_line():
    model = ikaros.Group("M")
    inner = model.group("Inner")
    c = model.module("Constant", "C", data="1")
    s = inner.module("Scale", "S")
    line = here() + 2
    with pytest.raises(ikaros.ModelError) as e:
        inner.connect(c.OUTPUT, s.INPUT)
    assert e.value.line == line and 'not inside group "Inner"' in str(e.value)


def test_an_element_read_from_a_file_keeps_its_file_line(tmp_path):
    path = tmp_path / "m.ikg"
    path.write_text('<?xml version="1.0"?>\n<group name="M">\n'
                    '    <module class="Nope" name="X"/>\n</group>\n')
    model = ikaros.Group.read(str(path))
    with pytest.raises(ikaros.ModelError) as e:
        model.build()
    assert (e.value.filename, e.value.line) == (str(path), 3)
    model.remove("X")
    line = here() + 1
    model.module("AlsoNope", "Y")
    with pytest.raises(ikaros.ModelError) as e:
        model.build()
    assert (e.value.filename, e.value.line) == (__file__, line)


def test_ports_are_listed_for_completion_and_reached_by_name():
    model = ikaros.Group("M")
    pid = model.module("PIDController", "PID")
    double = model.module(Doubler, "D")
    assert {"INPUT", "SETPOINT", "OUTPUT", "GATED"} <= set(dir(pid))
    assert {"INPUT", "OUTPUT", "set", "connect"} - set(dir(double)) == {"connect"}
    assert "OUTPUT" not in dir(model.module("NoSuchClass", "X"))
    assert pid.port("set").name == "set" and pid.port("set").address(model) == "PID.set"
