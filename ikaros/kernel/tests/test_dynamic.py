"""Dynamic outputs (Ikaros 3 ``dynamic="yes"`` with a ``capacity``): the DynamicArray a
module sees, their declaration, the connections they may feed, and their delays."""
import numpy as np
import pytest

import ikaros
from ikaros.dynamic import DynamicArray
from ikaros.experiments.signals import select_outputs
from ikaros.kernel import state
from ikaros.language.classfile import read_class_file
from ikaros.module import Output

# A source whose output on tick t has t % 3 + 1 rows of [t, row]; and a sink that keeps the
# shapes it saw.
CLASSES = '''
import numpy as np
from ikaros.module import Input, Module, Output, Parameter


class Rows(Module):
    """A dynamic output of t % 3 + 1 rows [t, row] on tick t."""
    rows = Parameter(3, "capacity rows")
    OUTPUT = Output("rows", dynamic=True, capacity="@rows, 2")

    def tick(self):
        t = self.clock.tick
        self.OUTPUT.clear()
        for r in range(t % 3 + 1):
            self.OUTPUT.append([t, r])


class Seen(Module):
    """Keeps the shape and the values of INPUT on every tick; OUTPUT is its row count."""
    INPUT = Input("a dynamic matrix")
    OUTPUT = Output("rows of INPUT", shape="1")

    def init(self):
        self.seen = []

    def tick(self):
        self.seen.append(np.asarray(self.INPUT).tolist())
        self.OUTPUT[0] = len(self.INPUT)


class Added(Module):
    """A dynamic output added in configure, capacity 4; holds the tick, tick + 1 rows."""
    def configure(self):
        self.add_output("OUTPUT", capacity=(4,))

    def tick(self):
        self.OUTPUT.set([self.clock.tick] * (self.clock.tick % 4 + 1))


class TooMany(Module):
    """Writes tick + 1 values: more than its capacity on tick 2."""
    OUTPUT = Output("rows", dynamic=True, capacity="2")

    def tick(self):
        self.OUTPUT.resize(self.clock.tick + 1)
'''


def rows(t: int) -> list:
    """What Rows outputs on tick t (no rows before tick 0)."""
    return [[t, r] for r in range(t % 3 + 1)] if t >= 0 else []


def _model(tmp_path, body: str, **overrides):
    header, *classes = CLASSES.split("\n\nclass ")
    for code in classes:                # one file per class, named after it
        name = code.split("(")[0]
        (tmp_path / f"{name}.py").write_text(f"{header}\n\nclass {code}")
    # Ikaros 2 files (a group port without an alias would make one an Ikaros 3 file)
    (tmp_path / "m.ikg").write_text(f'<group name="G" dialect="2">{body}</group>')
    return ikaros.load(str(tmp_path / "m.ikg"), **overrides)


def _seen(net, name: str) -> list:
    return net.modules[name].module.seen


# --- the array --------------------------------------------------------------------------
def test_dynamic_array_changes_shape_within_its_capacity():
    a = DynamicArray((3, 2))
    assert a.shape == (0, 2) and a.capacity == (3, 2) and len(a) == 0
    a.set([[1, 2], [3, 4]])
    a.append([5, 6])
    assert a.shape == (3, 2) and a.data.tolist() == [[1, 2], [3, 4], [5, 6]]
    a.resize((1, 2))
    assert a.data.tolist() == [[1, 2]]
    # operators, NumPy functions and array methods act on the current values
    assert (a * 2).tolist() == [[2, 4]] and float(np.sum(a)) == 3.0
    assert a.reshape(-1).tolist() == [1, 2] and a[0, 1] == 2
    np.multiply(a, 10, out=a)
    assert a.data.tolist() == [[10, 20]]
    b = DynamicArray((3, 2))
    b.assign(a)
    assert b.shape == (1, 2) and b.data.tolist() == [[10, 20]]
    for bad in ((4, 2), (1, 3), (2,)):
        with pytest.raises(ValueError, match="does not fit the capacity"):
            a.resize(bad)
    a.set(np.zeros((0, 2)))
    assert a.shape == (0, 2)


def test_a_dynamic_output_needs_a_capacity_and_no_other_size_rule():
    with pytest.raises(TypeError, match="needs a capacity"):
        Output("x", dynamic=True)
    with pytest.raises(TypeError, match="capacity is for dynamic outputs"):
        Output("x", capacity="3")
    with pytest.raises(TypeError, match="not by shape"):
        Output("x", dynamic=True, capacity="3", shape="3")
    spec = Output("x", dynamic=True, capacity="@n, 2").spec()
    assert spec.dynamic and spec.rule == {"capacity": "@n, 2"}
    assert spec.to_dict()["dynamic"] is True


def test_class_file_declares_a_dynamic_output(tmp_path):
    (tmp_path / "D.ikc").write_text('<class name="D"><output name="ROWS" dynamic="yes" '
                                    'capacity="128,2"/></class>')
    spec = read_class_file(str(tmp_path / "D.ikc")).outputs[0]
    assert spec.dynamic and spec.rule == {"capacity": "128,2"}
    (tmp_path / "E.ikc").write_text('<class name="E">\n<output name="ROWS" dynamic="yes"/>'
                                    '</class>')
    with pytest.raises(ikaros.ModelError, match=r'E.ikc:2: .*output "ROWS": a dynamic '
                                                r'output needs a capacity'):
        read_class_file(str(tmp_path / "E.ikc"))


# --- connections and delays -------------------------------------------------------------
def test_zero_delay_shares_the_output_and_delays_carry_the_shapes_of_their_tick(tmp_path):
    net = _model(tmp_path, '''
        <module class="Rows" name="R"/>
        <module class="Seen" name="Now"/> <module class="Seen" name="One"/>
        <module class="Seen" name="Two"/>
        <group name="Inner">
            <input name="IN"/>
            <module class="Seen" name="Three"/>
            <connection source="IN" target="Three.INPUT" delay="2"/>
        </group>
        <connection source="R.OUTPUT" target="Now.INPUT" delay="0"/>
        <connection source="R.OUTPUT" target="One.INPUT"/>
        <connection source="R.OUTPUT" target="Two.INPUT" delay="2"/>
        <connection source="R.OUTPUT" target="Inner.IN"/>''')
    source = net.modules["R"].module.OUTPUT
    assert isinstance(source, DynamicArray) and source.capacity == (3, 2)
    assert net.modules["Now"].module.INPUT is source       # delay 0: the output itself
    assert net.modules["One"].module.INPUT is not source
    net.run(6)
    for name, delay in (("Now", 0), ("One", 1), ("Two", 2), ("Inner.Three", 3)):
        assert _seen(net, name) == [rows(t - delay) for t in range(6)], name
    assert net.output("R.OUTPUT").tolist() == rows(5)
    assert net.output("One.INPUT").tolist() == rows(4)
    assert net.output("Now.OUTPUT").tolist() == [3]
    net.close()


def test_capacity_from_a_parameter_and_from_configure(tmp_path):
    net = _model(tmp_path, '''<module class="Rows" name="R" rows="5"/>
        <module class="Added" name="A"/> <module class="Seen" name="S"/>
        <connection source="A.OUTPUT" target="S.INPUT"/>''')
    assert net.modules["R"].module.OUTPUT.capacity == (5, 2)
    net.run(3)
    assert _seen(net, "S") == [[], [0], [1, 1]]
    assert "output OUTPUT: dynamic, capacity 4" in net.info()
    net.close()


def test_a_shape_beyond_the_capacity_stops_the_run_naming_the_module(tmp_path):
    net = _model(tmp_path, '<module class="TooMany" name="T"/>')
    net.run(2)
    with pytest.raises(ikaros.RunError, match=r"T: .*shape \(3,\) does not fit the "
                                              r"capacity \(2,\)"):
        net.step()


@pytest.mark.parametrize("connection, message", [
    ('source="R.OUTPUT[0]" target="S.INPUT"', "only support whole-matrix connections"),
    ('source="R.OUTPUT" target="S.INPUT[0:6]"', "only support whole-matrix connections"),
    ('source="R.OUTPUT" target="S.INPUT" sourceoffset="2" size="2"',
     "only support whole-matrix connections"),
    ('source="R.OUTPUT" target="S.INPUT" delay="1:2"', "only a single whole-matrix delay"),
    ('source="R.OUTPUT" target="S.INPUT" delay="0,2"', "only a single whole-matrix delay"),
])
def test_connections_a_dynamic_output_cannot_feed(tmp_path, connection, message):
    with pytest.raises(ikaros.ModelError, match=rf"m.ikg:1: <connection>: R.OUTPUT is "
                                                rf"dynamic: .*{message}"):
        _model(tmp_path, f'<module class="Rows" name="R"/><module class="Seen" name="S"/>'
                         f'<connection {connection}/>')


def test_an_input_fed_by_a_dynamic_output_takes_no_other_connection(tmp_path):
    with pytest.raises(ikaros.ModelError, match="S.INPUT is fed by the dynamic output "
                                                "R.OUTPUT, so it can take no other"):
        _model(tmp_path, '''<module class="Rows" name="R"/><module class="Seen" name="S"/>
            <module class="Constant" name="K" data="1 2"/>
            <connection source="R.OUTPUT" target="S.INPUT"/>
            <connection source="K.OUTPUT" target="S.INPUT"/>''')
    with pytest.raises(ikaros.ModelError, match="cannot be stacked"):
        _model(tmp_path, '''<module class="Rows" name="R"/>
            <module class="Seen" name="S" INPUT.stack="yes"/>
            <connection source="R.OUTPUT" target="S.INPUT"/>''')
    # through a group port that also takes another connection
    with pytest.raises(ikaros.ModelError, match="Inner.IN is fed by the dynamic output"):
        _model(tmp_path, '''<module class="Rows" name="R"/>
            <module class="Constant" name="K" data="1 2"/>
            <group name="Inner"><input name="IN"/><module class="Seen" name="S"/>
                <connection source="IN" target="S.INPUT"/></group>
            <connection source="R.OUTPUT" target="Inner.IN"/>
            <connection source="K.OUTPUT" target="Inner.IN"/>''')


def test_asynchronous_modules_take_no_dynamic_buffers(tmp_path):
    with pytest.raises(ikaros.ModelError, match="asynchronous module"):
        _model(tmp_path, '<module class="Rows" name="R" async="yes"/>')
    with pytest.raises(ikaros.ModelError, match="asynchronous module"):
        _model(tmp_path, '''<module class="Rows" name="R"/>
            <module class="Seen" name="S" async="yes"/>
            <connection source="R.OUTPUT" target="S.INPUT"/>''')


def test_a_capacity_that_never_resolves_names_the_output(tmp_path):
    (tmp_path / "C.py").write_text('''
from ikaros.module import Input, Module, Output
class C(Module):
    INPUT = Input("x", optional=True)
    OUTPUT = Output("y", dynamic=True, capacity="INPUT.rows, 2")
''')
    with pytest.raises(ikaros.ModelError, match=r'the capacity of dynamic output "OUTPUT" '
                                                r'of A could not be resolved'):
        _model(tmp_path, '<module class="C" name="A"/>'
                         '<connection source="A.OUTPUT" target="A.INPUT"/>')


# --- what fixed-size buffers keep -------------------------------------------------------
def test_dynamic_buffers_live_outside_the_arena_and_are_not_recorded(tmp_path):
    net = _model(tmp_path, '''<module class="Rows" name="R"/>
        <module class="Seen" name="S"/><module class="Seen" name="T"/>
        <connection source="R.OUTPUT" target="S.INPUT"/>
        <connection source="R.OUTPUT" target="T.INPUT" delay="3"/>''')
    buffers = {b.path: b for inst in net.schedule for ports in net._buffers[inst]
               for b in ports.values()}
    for path in ("R.OUTPUT", "S.INPUT", "T.INPUT"):
        assert buffers[path].dynamic and buffers[path].offset is None, path
    assert buffers["S.OUTPUT"].offset is not None        # fixed buffers: in the arena
    assert not net.rings and list(net.dynamic_rings) == [buffers["R.OUTPUT"]]
    signals, _ = select_outputs(net)
    assert [s.name for s in signals] == ["S.OUTPUT", "T.OUTPUT"]
    net.close()


def test_a_model_without_dynamic_outputs_has_no_dynamic_copies(tmp_path):
    net = _model(tmp_path, '''<module class="Constant" name="K" data="1 2"/>
        <module class="Scale" name="S"/><connection source="K.OUTPUT" target="S.INPUT"
        delay="3"/>''')
    assert net.dynamic_rings == {} and len(net._ring_list) == 1
    assert all(b.dynamic_array is None for inst in net.schedule
               for ports in net._buffers[inst] for b in ports.values())
    net.close()


def test_state_keeps_the_shape_of_a_dynamic_output(tmp_path):
    net = _model(tmp_path, '<module class="Rows" name="R"/>')
    assert net.output("R.OUTPUT").shape == (0, 2)
    net.run(2)
    state.save(net, str(tmp_path / "s.json"))
    net.run(1)
    assert net.output("R.OUTPUT").tolist() == rows(2)
    state.load(net, str(tmp_path / "s.json"))
    assert net.output("R.OUTPUT").tolist() == rows(1)
    state.reset(net)
    assert net.output("R.OUTPUT").shape == (0, 2)      # as after init: no rows
    text = (tmp_path / "s.json").read_text().replace("[[1.0, 0.0], [1.0, 1.0]]",
                                                     "[[1, 0], [1, 1], [1, 2], [1, 3]]")
    (tmp_path / "t.json").write_text(text)
    with pytest.raises(state.StateError, match=r'item "R.OUTPUT" has shape \[4, 2\], which '
                                               r'does not fit the capacity \[3, 2\]'):
        state.load(net, str(tmp_path / "t.json"))
    net.close()


def test_a_reset_empties_the_delay_line_of_a_dynamic_output(tmp_path):
    net = _model(tmp_path, '''<module class="Rows" name="R"/><module class="Seen" name="S"/>
        <connection source="R.OUTPUT" target="S.INPUT" delay="3"/>''')
    net.run(5)
    state.reset(net)
    net.run(4)
    # after the reset (tick 0 again) the delay line holds no rows until tick 3
    assert _seen(net, "S")[5:] == [[], [], [], rows(0)]
    net.close()


def test_the_compiled_tick_leaves_modules_with_dynamic_buffers_to_python(tmp_path):
    pytest.importorskip("numba", reason="the compiled tick needs numba (pip install "
                                        "ikaros[fast])")
    body = '''<module class="Rows" name="R"/><module class="Sum" name="Total"/>
        <module class="Constant" name="K" data="1 2 3"/><module class="Sum" name="Fixed"/>
        <connection source="R.OUTPUT" target="Total.INPUT" delay="0"/>
        <connection source="K.OUTPUT" target="Fixed.INPUT" delay="0"/>'''
    for compiled in ("no", "yes"):
        net = _model(tmp_path, body, compiled=compiled)
        if compiled == "yes":      # Sum is compiled, except where its input is dynamic
            assert {inst.path for inst in net.plan.fused} == {"K", "Fixed"}
        totals = []
        for _ in range(5):
            net.step()
            totals.append(float(net.output("Total.OUTPUT")[0]))
        net.close()
        # the current rows only, never what is left in the capacity beyond them
        assert totals == [float(np.sum(rows(t))) for t in range(5)], compiled
