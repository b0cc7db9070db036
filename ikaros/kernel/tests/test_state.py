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
