"""What a build leaves for the garbage collector: a large build's objects are frozen until the
network is closed, and modules of a class share its port tables until one adds a port."""
from __future__ import annotations

import gc
from types import SimpleNamespace

import numpy as np
import pytest

import ikaros
from ikaros.kernel import builder

CHAIN = '''<group name="G">
  <module class="Constant" name="C" data="1 2 3"/>
  <module class="Scale" name="S1" factor="2"/>
  <module class="Scale" name="S2" factor="3"/>
  <connection source="C.OUTPUT" target="S1.INPUT" delay="0"/>
  <connection source="S1.OUTPUT" target="S2.INPUT" delay="0"/>
</group>'''

TAPS = '''
from ikaros.module import Input, Module, Output, Parameter


class Taps(Module):
    """Test class: adds an input and an output named by its parameter, if any."""
    extra = Parameter("", "the name of an extra input and output")
    INPUT = Input("the signal")
    OUTPUT = Output("a copy", size_set="INPUT")

    def configure(self):
        if self.extra:
            self.add_input(self.extra, optional=True)
            self.add_output(self.extra + "_OUT", shape=(2,))

    def tick(self):
        self.OUTPUT[:] = self.INPUT
'''

TAPS_MODEL = '''<group name="G">
  <module class="Constant" name="C" data="1 2"/>
  <module class="Taps" name="A" extra="MORE"/>
  <module class="Taps" name="B"/>
  <connection source="C.OUTPUT" target="A.INPUT"/>
  <connection source="C.OUTPUT" target="B.INPUT"/>
  <connection source="C.OUTPUT" target="A.MORE"/>
</group>'''


@pytest.fixture
def chain(tmp_path):
    path = tmp_path / "chain.ikg"
    path.write_text(CHAIN)
    return str(path)


@pytest.fixture
def collector_on():
    assert gc.isenabled() and gc.get_freeze_count() == 0
    yield
    gc.unfreeze()        # whatever a failed test left frozen


def test_a_large_build_freezes_its_objects_until_close(chain, monkeypatch, collector_on):
    monkeypatch.setattr(builder, "FREEZE_MINIMUM", 10)
    net = ikaros.load(chain)
    assert net.frozen_objects is True
    frozen = gc.get_freeze_count()
    assert frozen > 10
    assert gc.isenabled()
    net.run(2)
    np.testing.assert_array_equal(net.output("S2.OUTPUT"), [6, 12, 18])
    net.close()
    assert net.frozen_objects is False
    assert gc.get_freeze_count() == 0
    net.close()                          # a second close changes nothing
    assert gc.get_freeze_count() == 0


def test_a_small_build_freezes_nothing(chain, collector_on):
    net = ikaros.load(chain)
    assert net.frozen_objects is False
    assert gc.get_freeze_count() == 0
    net.close()
    assert gc.get_freeze_count() == 0


def test_a_build_that_fails_turns_the_collector_back_on(tmp_path, monkeypatch, collector_on):
    monkeypatch.setattr(builder, "FREEZE_MINIMUM", 10)
    path = tmp_path / "bad.ikg"
    path.write_text(CHAIN.replace('target="S2.INPUT"', 'target="S9.INPUT"'))
    with pytest.raises(ikaros.ModelError, match="S9"):
        ikaros.load(str(path))
    assert gc.isenabled()
    assert gc.get_freeze_count() == 0


def test_a_port_added_in_configure_is_the_modules_own(tmp_path):
    (tmp_path / "Taps.py").write_text(TAPS)
    path = tmp_path / "taps.ikg"
    path.write_text(TAPS_MODEL)
    net = ikaros.load(str(path))
    a, b = net.modules["A"].module, net.modules["B"].module
    assert set(a._ik_inputs) == {"INPUT", "MORE"} and set(a._ik_outputs) == {"OUTPUT",
                                                                            "MORE_OUT"}
    assert set(b._ik_inputs) == {"INPUT"} and set(b._ik_outputs) == {"OUTPUT"}
    assert set(type(b)()._ik_inputs) == {"INPUT"}
    assert a.connected("MORE") and not b.connected("MORE")
    assert net.output("A.MORE_OUT").shape == (2,)
    with pytest.raises(KeyError):
        net.output("B.MORE_OUT")
    net.run(1)
    np.testing.assert_array_equal(net.output("B.OUTPUT"), [1, 2])
    net.close()


class _M:
    def __init__(self, name, order):
        self.name, self.order, self.path = name, order, name


def test_schedule_keeps_declaration_order_when_it_works_and_sorts_otherwise():
    from ikaros.kernel.schedule import schedule
    a, b, c, d = (_M(n, k) for k, n in enumerate("ABCD"))
    forward = {(a, c): "n1", (b, c): "n2", (c, d): "n3"}
    assert [m.name for m in schedule([a, b, c, d], forward)] == ["A", "B", "C", "D"]
    backward = {(d, a): "n1", (c, b): "n2"}      # D feeds A, C feeds B
    assert [m.name for m in schedule([a, b, c, d], backward)] == ["C", "B", "D", "A"]
    node = SimpleNamespace(error=lambda message: ValueError(message))
    with pytest.raises(ValueError, match="zero-delay cycle: B -> A -> B"):
        schedule([a, b, c, d], {(a, b): node, (b, a): node})
    with pytest.raises(ValueError, match="zero-delay cycle: A -> A"):
        schedule([a, b], {(a, a): node})
