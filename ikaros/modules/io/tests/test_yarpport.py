"""Tests of YARPPort: the Bottles it writes and reads, through a stand-in for YARP's Python
bindings (the bindings are not on PyPI; without them the model fails at load, which is
tested too)."""
import sys
import types

import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load


class Value:
    def __init__(self, v):
        self.v = v

    def asFloat64(self):
        return self.v


class Bottle:
    def __init__(self, values=()):
        self.values = list(values)

    def clear(self):
        self.values = []

    def addFloat64(self, v):
        assert type(v) is float
        self.values.append(v)

    def size(self):
        return len(self.values)

    def get(self, i):
        return Value(self.values[i])


class Network:
    """The name server and the connections: port name -> port, (from, to) pairs."""
    ports, connections, up, initialised = {}, [], True, 0

    @classmethod
    def init(cls):
        cls.initialised += 1

    @classmethod
    def fini(cls):
        cls.initialised -= 1

    @classmethod
    def checkNetwork(cls):
        return cls.up

    @classmethod
    def connect(cls, source, target):
        cls.connections.append((source, target))
        return True


class BufferedPortBottle:
    def __init__(self):
        self.written, self.incoming, self.strict, self.name = [], [], False, None

    def open(self, name):
        self.name = name
        Network.ports[name] = self
        return True

    def prepare(self):
        self.bottle = Bottle()
        return self.bottle

    def write(self, strict=False):
        self.written.append((list(self.bottle.values), strict))

    def setStrict(self, strict):
        self.strict = strict

    def read(self, wait=True):
        if not self.incoming:
            return None
        if self.strict:
            return self.incoming.pop(0)
        newest = self.incoming[-1]
        self.incoming.clear()
        return newest

    def close(self):
        Network.ports.pop(self.name)


@pytest.fixture
def yarp(monkeypatch):
    module = types.ModuleType("yarp")
    module.Network, module.BufferedPortBottle, module.Bottle = Network, BufferedPortBottle, \
        Bottle
    Network.ports, Network.connections, Network.up, Network.initialised = {}, [], True, 0
    monkeypatch.setitem(sys.modules, "yarp", module)
    return Network


def test_a_sender_writes_a_bottle_of_its_input_when_it_changes(tmp_path, yarp):
    (tmp_path / "in.txt").write_text("A/2 B/1\n1 2 3\n1 2 3\n4 5 6\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="in.txt"/>'
                         '<module class="YARPPort" name="Out" connect="/robot/in" '
                         'send_strict="yes"/>'
                         '<connection source="F.A" target="Out.INPUT" delay="0"/>'
                         '<connection source="F.B" target="Out.INPUT" delay="0"/>')
    try:
        port = yarp.ports["/ikaros/Out"]
        assert yarp.connections == [("/ikaros/Out", "/robot/in")]
        activity = []
        for _ in range(3):
            net.step()
            activity.append(net.output("Out.YARP_ACTIVITY")[0])
        # INPUT is B then A: the connection declared last comes first (Ikaros 2)
        assert port.written == [([3.0, 1.0, 2.0], True), ([6.0, 4.0, 5.0], True)]
        assert activity == [1, 0, 1]
    finally:
        net.close()
    assert yarp.ports == {} and yarp.initialised == 0


def test_a_sender_of_every_tick(tmp_path, yarp):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; 3 4"/>'
                         '<module class="YARPPort" name="Out" port_name="/me" '
                         'send_only_new_values="no"/>'
                         '<connection source="C.OUTPUT" target="Out.INPUT"/>')
    try:
        net.run(ticks=3)
        assert yarp.ports["/me"].written == [([1.0, 2.0, 3.0, 4.0], False)] * 3
    finally:
        net.close()


@pytest.mark.parametrize("strict, expected", [("no", [[7, 8, 9], [7, 8, 9], [7, 8, 9]]),
                                              ("yes", [[1, 2, 0], [4, 5, 6], [7, 8, 9]])])
def test_a_receiver_reads_the_newest_or_every_bottle(tmp_path, yarp, strict, expected):
    net = load(tmp_path, f'<module class="YARPPort" name="In" type="receiver" '
                         f'outputsize="3" receive_strict="{strict}" connect="/cam"/>')
    try:
        port = yarp.ports["/ikaros/In"]
        assert yarp.connections == [("/cam", "/ikaros/In")]
        assert port.strict == (strict == "yes")
        net.step()
        assert net.output("In.YARP_ACTIVITY").tolist() == [0]
        port.incoming += [Bottle([1, 2]), Bottle([4, 5, 6]), Bottle([7, 8, 9, 10])]
        seen = []
        for _ in range(3):
            net.step()
            seen.append(net.output("In.OUTPUT").tolist())
        assert seen == expected
    finally:
        net.close()


def test_a_receiver_of_rows_and_columns(tmp_path, yarp):
    net = load(tmp_path, '<module class="YARPPort" name="In" type="receiver" '
                         'outputsize_x="2" outputsize_y="2"/>')
    try:
        yarp.ports["/ikaros/In"].incoming.append(Bottle([1, 2, 3, 4]))
        net.step()
        assert net.output("In.OUTPUT").tolist() == [[1, 2], [3, 4]]
        assert net.output("In.YARP_ACTIVITY").tolist() == [1]
    finally:
        net.close()


def test_errors(tmp_path, yarp, monkeypatch):
    with pytest.raises(ModelError, match="needs outputsize"):
        load(tmp_path, '<module class="YARPPort" name="In" type="receiver"/>')
    yarp.up = False
    with pytest.raises(ModelError, match="no YARP name server"):
        load(tmp_path, '<module class="YARPPort" name="In" type="receiver" outputsize="1"/>')
    monkeypatch.setitem(sys.modules, "yarp", None)            # the bindings are missing
    with pytest.raises(ModelError, match="conda install -c conda-forge yarp"):
        load(tmp_path, '<module class="YARPPort" name="In" type="receiver" outputsize="1"/>')
