"""Changing a running model: modules that did not change keep their state."""
import numpy as np
import pytest

import ikaros
from ikaros.language.node import Node


class Counter(ikaros.Module):
    """Counts its ticks in a Python attribute."""
    OUTPUT = ikaros.Output("the count", shape="1")

    def init(self):
        self.count = 0

    def tick(self):
        self.count += 1
        self.OUTPUT[0] = self.count


def integrating_model():
    model = ikaros.Group("M")
    one = model.module("Constant", "One", data="1")
    total = model.module("Integrator", "Total", alpha=1, beta=1)
    model.connect(one.OUTPUT, total.INPUT)
    return model, one, total


def test_an_integrator_keeps_its_value_through_an_unrelated_change():
    model, one, total = integrating_model()
    net = model.build()
    net.run(ticks=5)
    assert net.output("Total.OUTPUT").tolist() == [5.0]   # Constant's value is there from init
    extra = model.module("Scale", "Extra", factor=3)
    model.connect(one.OUTPUT, extra.INPUT, delay=0)
    old = net
    net = net.apply(model)
    assert old.stopped and net is not old
    assert net.tick == 5
    assert net.output("Total.OUTPUT").tolist() == [5.0]
    net.run(ticks=2)
    assert net.output("Total.OUTPUT").tolist() == [7.0]
    assert net.output("Extra.OUTPUT").tolist() == [3.0]


def test_a_changed_module_starts_afresh_and_the_others_keep_their_state():
    model, one, total = integrating_model()
    model.module(Counter, "Count")
    net = model.build()
    net.run(ticks=4)
    total.set(beta=2)                   # a changed parameter: Total is a new module
    net = net.apply(model)
    assert net.output("Total.OUTPUT").tolist() == [0.0]
    net.step()
    assert net.output("Total.OUTPUT").tolist() == [2.0]
    assert net.output("Count.OUTPUT").tolist() == [5.0]      # counted on: 4, then 5


def test_a_removed_and_a_reconnected_module():
    model, one, total = integrating_model()
    two = model.module("Constant", "Two", data="2")
    net = model.build()
    net.run(ticks=3)
    model.disconnect(one.OUTPUT, total.INPUT)
    model.connect(two.OUTPUT, total.INPUT)
    model.remove("One")
    net = net.apply(model)
    assert "One" not in net.modules
    net.step()
    assert net.output("Total.OUTPUT").tolist() == [5.0]       # 3, then + 2


def test_delayed_outputs_keep_their_history():
    model = ikaros.Group("M")
    ramp = model.module("Sweep", "Ramp", min=0, max=100, step=1)
    late = model.module("Scale", "Late", factor=1)
    model.connect(ramp.OUTPUT, late.INPUT, delay=3)
    reference = model.build()
    reference.run(ticks=5)
    net = model.build()
    net.run(ticks=5)
    model.module("Constant", "Other", data="0")
    net = net.apply(model)
    for _ in range(3):
        net.step()
        reference.step()
        assert net.output("Late.OUTPUT").tolist() == reference.output("Late.OUTPUT").tolist()
    assert net.output("Late.OUTPUT").tolist() == [5.0]


def test_a_model_that_does_not_build_leaves_the_network_running():
    model, one, total = integrating_model()
    net = model.build()
    net.run(ticks=2)
    model.module("NoSuchClass", "Bad")
    with pytest.raises(ikaros.ModelError, match="NoSuchClass"):
        net.apply(model)
    assert not net.stopped
    net.step()
    assert np.array_equal(net.output("Total.OUTPUT"), [3.0])


def test_an_edit_keeps_the_dialect_and_the_clock_of_the_running_network(tmp_path):
    """A file read as Ikaros 3 (by its class Clip) stays Ikaros 3 when the edit adds a
    module whose spaced matrix alone would make it an Ikaros 2 file: the tick numbering and
    every class's dialect go on as they were; a model that names its dialect gets it."""
    path = tmp_path / "m.ikg"
    path.write_text('<group name="M"><module class="Constant" name="C" data="2"/>'
                    '<module class="Clip" name="K"/><module class="System" name="S"/>'
                    '<connection source="C.OUTPUT" target="K.INPUT"/></group>')
    net = ikaros.load(str(path), quiet=True)
    assert net.dialect == "3"
    net.run(ticks=3)
    tree = net.model.copy()
    tree.children.append(Node("module", {"class": "Constant", "name": "D", "data": "1 2 3"}))
    net = net.apply(tree)
    assert net.dialect == "3"
    net.step()
    assert net.output("S.TICK").tolist() == [4.0]     # Ikaros 3 numbers the first tick 1
    named = net.model.copy()
    named.attrs["dialect"] = "2"
    net = net.apply(named)
    assert net.dialect == "2"
    net.close()
