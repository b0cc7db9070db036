"""A module kept by Apply (``net.apply``) goes on as the same module: what it holds follows
the new network's buffers (kernel/follow.py), its init does not run again and the replaced
network does not stop it (issue 37: Add kept views of the replaced network's inputs)."""
import numpy as np
import pytest

import ikaros
from ikaros.kernel.builder import Builder
from ikaros.kernel.codeclasses import CodeClassRegistry
from ikaros.module import WARNING

EVENTS: list = []


class Helper:
    """Holds views of the module's ports, as a helper object of a user module might."""

    def __init__(self, source, target):
        self.source, self.target = source, target

    def run(self):
        np.multiply(self.source, 2, out=self.target)


class Holder(ikaros.Module):
    """OUTPUT = 2 * INPUT + 1 * (the number of ticks), computed through everything a module
    may keep of its ports: views in a list, a dict, a tuple, a helper object, a closure, a
    bound method of a port array and a reshaped view."""
    INPUT = ikaros.Input("the signal")
    OUTPUT = ikaros.Output("2 * INPUT + ticks", shape="INPUT.shape")

    def init(self):
        EVENTS.append(("init", self.path))
        self.ticks = 0
        flat_in, flat_out = self.INPUT.reshape(-1), self.OUTPUT.reshape(-1)
        self.views = [flat_in, {"out": flat_out}, (self.INPUT, self.OUTPUT)]
        self.helper = Helper(self.INPUT, self.OUTPUT)
        out = self.OUTPUT

        def add_ticks():
            out[...] += self.ticks
        self.add_ticks = add_ticks
        self.clear = self.OUTPUT.fill

    def tick(self):
        self.ticks += 1
        self.clear(0)
        self.helper.run()
        self.add_ticks()
        assert self.views[0] is not None and self.views[1]["out"].size == self.OUTPUT.size

    def stop(self):
        EVENTS.append(("stop", self.path))


class Spanning(ikaros.Module):
    """Keeps the memory all buffers share (its input's base), which no new buffer matches."""
    INPUT = ikaros.Input("the signal")
    OUTPUT = ikaros.Output("the input", shape="INPUT.shape")

    def init(self):
        EVENTS.append(("init", self.path))
        self.everything = self.INPUT.base

    def tick(self):
        self.OUTPUT[...] = self.INPUT


class Ender(ikaros.Module):
    """Ends the run on its third tick."""

    def tick(self):
        if self.clock.tick == 2:
            self.end_of_file()


def model(cls=Holder):
    m = ikaros.Group("M")
    ramp = m.module("Sweep", "Ramp", min=0, max=100, step=1, outputsize=2)
    keep = m.module(cls, "Keep")
    m.connect(ramp.OUTPUT, keep.INPUT, delay=0)
    return m


def moved(m):
    """The model with a module added before the others: every buffer moves."""
    m.module("Constant", "Extra", data="1 2 3 4 5")
    m.node.children.insert(0, m.node.children.pop())
    return m


@pytest.fixture(autouse=True)
def events():
    EVENTS.clear()
    yield EVENTS


def test_everything_a_kept_module_holds_follows_the_new_buffers():
    reference = model().build()
    reference.run(ticks=8)
    EVENTS.clear()
    m = model()
    net = m.build()
    net.run(ticks=4)
    net = net.apply(moved(m))
    try:
        for _ in range(4):
            net.step()
        assert net.output("Keep.OUTPUT").tolist() == reference.output("Keep.OUTPUT").tolist()
        # (the ramp is at 8 on the 8th tick)
        assert net.output("Keep.OUTPUT").tolist() == [2 * 8 + 8, 2 * 8 + 8]
        assert EVENTS == [("init", "Keep")]         # the same module, started once
    finally:
        net.close()
        reference.close()
    assert EVENTS == [("init", "Keep"), ("stop", "Keep"), ("stop", "Keep")]   # and the reference


def test_a_kept_module_is_not_stopped_by_the_replaced_network_and_stops_once():
    m = model()
    net = m.build()
    net.run(ticks=2)
    net = net.apply(m)
    net = net.apply(m)
    assert EVENTS == [("init", "Keep")]
    net.close()
    assert EVENTS == [("init", "Keep"), ("stop", "Keep")]


def test_a_module_holding_memory_that_cannot_follow_starts_afresh_with_a_warning():
    m = model(Spanning)
    net = m.build()
    net.run(ticks=3)
    net = net.apply(moved(m))
    try:
        assert EVENTS == [("init", "Keep"), ("init", "Keep")]
        assert any(level == WARNING and where == "Keep" and "starts afresh" in text
                   for _, level, where, text in net.log)
        net.step()
        assert net.output("Keep.OUTPUT").tolist() == [4, 4]
    finally:
        net.close()


def test_after_the_run_has_ended_every_module_starts_afresh():
    m = model()
    m.module(Ender, "End")
    net = m.build()
    net.run()
    assert net.stopped and EVENTS == [("init", "Keep"), ("stop", "Keep")]
    m.remove("End")
    net = net.apply(m)
    try:
        assert EVENTS == [("init", "Keep"), ("stop", "Keep"), ("init", "Keep")]
        net.step()
        assert net.tick == 4
        # the ramp starts again too: its first tick gives 1
        assert net.output("Keep.OUTPUT").tolist() == [2 * 1 + 1, 2 * 1 + 1]
    finally:
        net.close()


def test_a_build_that_never_takes_over_leaves_the_running_network_whole():
    """The web UI abandons a build that takes too long: its kept modules never started, so
    closing it stops none of them, and the running network goes on."""
    m = model()
    net = m.build()
    net.run(ticks=2)
    tree, classes = m.model_tree()
    new = Builder(net.filename, model=tree, predecessor=net,
                  registry=CodeClassRegistry([], classes)).build()
    new.close()
    assert EVENTS == [("init", "Keep")]
    net.step()
    assert net.output("Keep.OUTPUT").tolist() == [2 * 3 + 3, 2 * 3 + 3]
    net.close()
    assert EVENTS == [("init", "Keep"), ("stop", "Keep")]
