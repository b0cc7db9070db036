"""Saving, loading and resetting a network's state (ikaros/kernel/state.py): outputs, delay
lines and the attributes a class declares in ``state``."""
from __future__ import annotations

import json

import numpy as np
import pytest

import ikaros
from ikaros.kernel import state

COUNTER = '''
import numpy as np
from ikaros.module import Input, Module, Output


class Counter(Module):
    """Test class: counts ticks and sums its input."""
    state = ("count", "total")
    INPUT = Input("added each tick")
    OUTPUT = Output("count and sum", shape=2)

    def init(self):
        self.count = 0
        self.total = np.zeros(1)

    def tick(self):
        self.count += 1
        self.total += self.INPUT.sum()
        self.OUTPUT[:] = (self.count, self.total[0])
'''

MODEL = '''<group name="G">
  <module class="FunctionGenerator" name="F" type="ramp" frequency="0.1"/>
  <module class="Counter" name="C"/>
  <module class="Add" name="A"/>
  <connection source="F.OUTPUT" target="C.INPUT" delay="3"/>
  <connection source="C.OUTPUT" target="A.INPUT1" delay="2"/>
  <connection source="C.OUTPUT" target="A.INPUT2" delay="1"/>
</group>'''


@pytest.fixture
def model(tmp_path):
    (tmp_path / "Counter.py").write_text(COUNTER)
    path = tmp_path / "m.ikg"
    path.write_text(MODEL)
    return str(path)


def outputs(net):
    return {p: net.output(p) for p in ("F.OUTPUT", "C.OUTPUT", "A.OUTPUT")}


def test_a_loaded_state_resumes_the_run_exactly(model, tmp_path):
    reference = ikaros.load(model)
    reference.run(6)
    header = state.save(reference, str(tmp_path / "s.state"))
    reference.run(5)
    expected = outputs(reference)
    reference.close()
    assert header["tick"] == 6 and header["scope"] == "network"
    assert header["item_count"] == 3 + 2 + 2     # outputs, delay lines of F and C, state

    items = json.loads((tmp_path / "s.state").read_text())["items"]
    assert items["C.count"] == {"kind": "state", "type": "int", "value": 6}
    assert items["F.OUTPUT@delay"]["shape"] == [2, 1]     # delay 3 keeps two older values

    fresh = ikaros.load(model)
    fresh.run(2)                                    # a different state, overwritten
    state.load(fresh, str(tmp_path / "s.state"))
    assert fresh.tick == 6
    fresh.run(5)
    got = outputs(fresh)
    fresh.close()
    for path, value in expected.items():
        np.testing.assert_array_equal(got[path], value, err_msg=path)
    assert expected["C.OUTPUT"][0] == 11


def test_reset_goes_back_to_the_state_after_init(model):
    net = ikaros.load(model)
    first = None
    net.run(4)
    first = outputs(net)
    net.run(3)
    state.reset(net)
    assert net.tick == 0 and net.modules["C"].module.count == 0
    net.run(4)
    again = outputs(net)
    net.close()
    for path, value in first.items():
        np.testing.assert_array_equal(again[path], value, err_msg=path)


def test_a_scoped_state_touches_only_its_module(model, tmp_path):
    net = ikaros.load(model)
    net.run(3)
    state.save(net, str(tmp_path / "c.state"), "C")
    net.run(2)
    f_before = net.output("F.OUTPUT")
    state.load(net, str(tmp_path / "c.state"), "C")
    assert net.tick == 5                            # a module's state leaves the tick
    assert net.output("C.OUTPUT")[0] == 3 and net.modules["C"].module.count == 3
    np.testing.assert_array_equal(net.output("F.OUTPUT"), f_before)
    with pytest.raises(state.StateError, match='holds the state of "C", not of "network"'):
        state.load(net, str(tmp_path / "c.state"))
    net.close()


def test_a_state_that_does_not_fit_changes_nothing(model, tmp_path):
    net = ikaros.load(model)
    net.run(3)
    state.save(net, str(tmp_path / "s.state"))
    data = json.loads((tmp_path / "s.state").read_text())
    before = outputs(net)

    def refused(change, message):
        broken = json.loads(json.dumps(data))
        change(broken)
        (tmp_path / "bad.state").write_text(json.dumps(broken))
        with pytest.raises(state.StateError, match=message):
            state.load(net, str(tmp_path / "bad.state"))
        for path, value in before.items():
            np.testing.assert_array_equal(net.output(path), value)
        assert net.tick == 3 and net.modules["C"].module.count == 3

    refused(lambda d: d["items"]["C.OUTPUT"].update(shape=[3], value=[1, 2, 3]),
            r'item "C.OUTPUT" has shape \[3\] but the target has shape \[2\]')
    refused(lambda d: d["items"]["C.count"].update(type="float", value=1.0),
            'item "C.count" has type "float" but target state has type "int"')
    refused(lambda d: d["items"]["C.count"].update(value="six"),
            'item "C.count": Expected integer value, not "six"')
    refused(lambda d: d["items"].pop("A.OUTPUT"), r"missing: A\.OUTPUT")
    refused(lambda d: d.update(format="other"), "unsupported format")
    refused(lambda d: d.pop("items"), "does not contain an items object")
    net.close()


def test_state_must_be_a_tuple_of_names():
    with pytest.raises(TypeError, match="Bad.state must be a tuple of attribute names"):
        class Bad(ikaros.Module):
            state = "count"


def test_startup_steps_are_timed(model):
    net = ikaros.load(model)
    steps = [s["step"] for s in net.startup.as_list()]
    net.close()
    assert steps == ["read the model file", "groups and modules", "classes and ports",
                     "connections", "sizes", "delays and schedule", "memory",
                     "compile the tick", "init of the modules"]


TYPED = '''
import numpy as np
from ikaros.module import Input, Module, Output, State


class Typed(Module):
    """Test class: declared state of every type."""
    INPUT = Input("summed into SUM")
    OUTPUT = Output("SUM times gain", shape="INPUT.shape")
    SUM = State(description="private matrix state", shape="INPUT.shape")
    gain = State(2.0, "a float")
    weight = State(0.5, type="double")
    steps = State(0)
    on = State(True)
    name_ = State("new", name="label")

    def tick(self):
        self.SUM += self.INPUT
        self.steps += 1
        self.OUTPUT[...] = self.SUM * self.gain
'''

TYPED_MODEL = '''<group name="T">
  <module class="Constant" name="C" data="1, 2"/>
  <module class="Typed" name="A"/>
  <module class="Typed" name="B"/>
  <connection source="C.OUTPUT" target="A.INPUT"/>
  <connection source="C.OUTPUT" target="B.INPUT"/>
</group>'''


@pytest.fixture
def typed(tmp_path):
    (tmp_path / "Typed.py").write_text(TYPED)
    path = tmp_path / "t.ikg"
    path.write_text(TYPED_MODEL)
    return str(path)


def test_declared_state_is_saved_with_its_types_and_is_not_a_port(typed, tmp_path):
    net = ikaros.load(typed)
    desc = net.modules["A"].module.description
    assert [(s.name, s.type, s.default) for s in desc.states] == [
        ("SUM", "matrix", None), ("gain", "float", 2.0), ("weight", "double", 0.5),
        ("steps", "int", 0), ("on", "bool", True), ("label", "string", "new")]
    net.run(3)
    net.modules["A"].module.label = "three"
    header = net.save_state(str(tmp_path / "s.state"))
    net.close()
    items = json.loads((tmp_path / "s.state").read_text())["items"]
    assert header["item_count"] == 1 + 2 * 7
    assert items["A.SUM"] == {"kind": "state", "type": "matrix", "shape": [2],
                              "value": [3.0, 6.0]}
    assert items["A.OUTPUT"]["value"] == [6.0, 12.0]
    assert {k: v["value"] for k, v in items.items() if k.startswith("A.") and
            v["type"] != "matrix"} == {"A.gain": 2.0, "A.weight": 0.5, "A.steps": 3,
                                       "A.on": True, "A.label": "three"}
    assert items["A.weight"]["type"] == "double" and items["A.gain"]["type"] == "float"


def test_network_state_methods_and_the_default_file(typed, tmp_path, capsys):
    net = ikaros.load(typed)
    assert net.state_file() == str(tmp_path / "t.state")
    net.run(2)
    net.save_state()
    assert f"Saved state to {tmp_path / 't.state'} (15 items, tick 2)" in capsys.readouterr().out
    net.run(2)
    net.reset_state("A")
    assert net.tick == 4 and net.modules["A"].module.steps == 0
    assert net.modules["B"].module.steps == 4
    net.close()
    again = ikaros.load(typed, load_state=True)
    assert "Loaded state from" in capsys.readouterr().out
    assert again.tick == 2 and again.modules["B"].module.steps == 2
    np.testing.assert_array_equal(again.modules["B"].module.SUM, [2, 4])
    again.close()


def test_a_scoped_state_loads_into_another_module_of_the_same_make(typed, tmp_path):
    net = ikaros.load(typed)
    net.run(2)
    net.modules["A"].module.label = "trained"
    net.save_state(str(tmp_path / "a.state"), "A")
    net.load_state(str(tmp_path / "a.state"), "B")
    b = net.modules["B"].module
    assert b.label == "trained" and b.steps == 2
    net.modules["A"].module.label = "changed"
    assert b.label == "trained"
    net.close()


def _original(tmp_path, items):
    (tmp_path / "v3.state").write_text(json.dumps({
        "format": "ikaros-state-v1", "tick": 4, "ikaros_version": "3.0",
        "model_name": "T", "scope": "network", "item_count": len(items), "items": items}))
    return str(tmp_path / "v3.state")


def test_a_state_file_of_ikaros_3_sets_the_items_it_holds(typed, tmp_path):
    net = ikaros.load(typed)
    net.run(1)
    net.load_state(_original(tmp_path, {
        "T.A.SUM": {"kind": "state", "type": "matrix", "shape": [2], "value": [5, 7]},
        "T.A.weight": {"kind": "state", "type": "double", "value": 0.25}}))
    a = net.modules["A"].module
    np.testing.assert_array_equal(a.SUM, [5, 7])
    assert (a.weight, a.steps, net.tick) == (0.25, 1, 4)
    with pytest.raises(ikaros.StateError, match=r"not in the network: A\.nothing"):
        net.load_state(_original(tmp_path, {"T.A.nothing": {"type": "int", "value": 1}}))
    with pytest.raises(ikaros.StateError,
                       match='item "A.weight" has type "float" but target state has type '
                             '"double"'):
        net.load_state(_original(tmp_path, {"T.A.weight": {"type": "float", "value": 1.0}}))
    net.close()


def test_bad_state_declarations_are_refused():
    with pytest.raises(TypeError, match="the default 'x' is not a int"):
        class BadDefault(ikaros.Module):
            n = ikaros.State("x", type="int")
    with pytest.raises(TypeError, match="a matrix state needs a shape"):
        class NoShape(ikaros.Module):
            m = ikaros.State(type="matrix")
    with pytest.raises(TypeError, match="the state n is declared twice"):
        class Twice(ikaros.Module):
            state = ("n",)
            n = ikaros.State(0)
    with pytest.raises(TypeError, match="the state OUTPUT is declared twice"):
        class AlsoAnOutput(ikaros.Module):
            OUTPUT = ikaros.Output(shape="1")

        class Sub(AlsoAnOutput):
            OUTPUT = ikaros.State(shape="2")


def test_delta_weights_are_state(tmp_path):
    path = tmp_path / "d.ikg"
    path.write_text('<group name="G"><module class="Constant" name="CS" data="1, 0"/>'
                    '<module class="Constant" name="US" data="2"/>'
                    '<module class="Delta" name="D" alpha="0.5"/>'
                    '<connection source="CS.OUTPUT" target="D.CS"/>'
                    '<connection source="US.OUTPUT" target="D.US"/></group>')
    net = ikaros.load(str(path))
    net.run(1)                                  # error 2: w = 0.5 * 2 * [1, 0]
    net.save_state()
    net.run(1)
    np.testing.assert_array_equal(net.modules["D"].module.weights, [1.5, 0])
    net.load_state()
    np.testing.assert_array_equal(net.modules["D"].module.weights, [1, 0])
    net.reset_state()
    np.testing.assert_array_equal(net.modules["D"].module.weights, [0, 0])
    net.close()


SLOW_COUNTER = '''
import time
from ikaros.module import Module, Output, State


class SlowCounter(Module):
    """Test class: each job takes 0.2 s, then counts in ``jobs`` and adds 1 to OUTPUT."""
    jobs = State(0, "jobs finished")
    OUTPUT = Output("jobs finished, added up on the output itself", shape=1)

    def tick(self):
        time.sleep(0.2)
        self.jobs += 1
        self.OUTPUT[0] += 1
'''


def test_an_asynchronous_module_is_saved_loaded_and_reset_between_two_jobs(tmp_path):
    """Save, load and reset wait for the running job (and publish it); a loaded or reset
    output is the one the module's next job goes on from."""
    (tmp_path / "SlowCounter.py").write_text(SLOW_COUNTER)
    path = tmp_path / "a.ikg"
    path.write_text('<group name="G"><module class="SlowCounter" name="S" async="yes"/>'
                    '</group>')
    net = ikaros.load(str(path))
    module = net.modules["S"].module
    net.step()                                          # job 1 runs
    state.save(net, str(tmp_path / "one.state"), "S")   # after job 1
    items = json.loads((tmp_path / "one.state").read_text())["items"]
    assert items["S.jobs"]["value"] == 1 and items["S.OUTPUT"]["value"] == [1.0]
    net.step()                                          # job 2 runs
    state.load(net, str(tmp_path / "one.state"), "S")   # after job 2: back to 1
    assert (net.output("S.OUTPUT").tolist(), module.jobs) == ([1.0], 1)
    net.step()                                          # job 3 goes on from 1
    state.save(net, str(tmp_path / "two.state"), "S")
    assert (net.output("S.OUTPUT").tolist(), module.jobs) == ([2.0], 2)
    net.step()                                          # job 4 runs
    state.reset(net, "S")                               # after job 4: back to 0
    assert (net.output("S.OUTPUT").tolist(), module.jobs) == ([0.0], 0)
    net.step()
    net.close()                                         # waits for job 5
    assert (net.output("S.OUTPUT").tolist(), module.jobs) == ([1.0], 1)
