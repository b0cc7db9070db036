"""YARPPort: sends or receives arrays on a YARP network."""
import numpy as np

from ikaros.module import Input, MissingDependency, Module, Output, Parameter

INSTALL = ("YARPPort needs YARP's Python bindings (the Python module yarp with "
           "yarp.BufferedPortBottle): install them with conda (conda install -c conda-forge "
           "yarp) or build YARP with its Python bindings (CMake options "
           "YARP_COMPILE_BINDINGS=ON and CREATE_PYTHON=ON); the PyPI package named yarp is "
           "another library")


def yarp_bindings():
    """The yarp module of YARP's bindings, or MissingDependency saying how to get it."""
    try:
        import yarp
    except ImportError:
        raise MissingDependency(INSTALL) from None
    if not hasattr(yarp, "BufferedPortBottle"):
        raise MissingDependency(INSTALL)
    return yarp


class YARPPort(Module):
    """Links a model to a YARP network (the robot middleware of the iCub) through YARP's
    Python bindings. As a ``sender`` it writes INPUT on the port ``port_name`` as a Bottle of
    its elements (64-bit floats, in order), every tick or, with ``send_only_new_values``, on
    ticks when INPUT has changed (and on the first); ``send_strict`` makes the port keep
    every message for slow readers instead of only the newest. As a ``receiver`` it reads
    Bottles of numbers from its port into OUTPUT (of outputsize, or outputsize_y rows of
    outputsize_x; a shorter Bottle fills the start and leaves the rest, a longer one is cut):
    the newest Bottle each tick, or with ``receive_strict`` the next one in order, so that
    none is lost. YARP_ACTIVITY is 1 on ticks when a Bottle was sent or received. With
    ``connect`` set, the port is connected to that YARP port at start (from it, for a
    receiver). A YARP name server (yarpserver) must be running. Without the bindings the
    model fails at load with a message saying how to install them. ``port_name`` and
    ``connect`` are this implementation's; the default name is /ikaros/ and the module's
    path with dots as slashes."""

    type = Parameter("sender", "send INPUT or receive into OUTPUT",
                     options="sender,receiver")
    port_name = Parameter("", "the YARP port's name (empty: /ikaros/ and the module's path)")
    connect = Parameter("", "a YARP port to connect to at start (empty: none)")
    send_only_new_values = Parameter(True, "sender: send only when INPUT has changed")
    send_strict = Parameter(False, "sender: keep every message for slow readers")
    receive_strict = Parameter(False, "receiver: read every message in order instead of "
                               "the newest")
    outputsize = Parameter(None, "receiver: the number of elements of a 1-D OUTPUT",
                           type="int")
    outputsize_x = Parameter(None, "receiver: the columns of a 2-D OUTPUT", type="int")
    outputsize_y = Parameter(None, "receiver: the rows of a 2-D OUTPUT", type="int")

    INPUT = Input("sender: the values to send", optional=True)
    OUTPUT = Output("receiver: the values received", optional=True)
    YARP_ACTIVITY = Output("1 on ticks when a Bottle was sent or received", size=1)

    def configure(self):
        self._yarp = yarp_bindings()
        if self.type == "receiver":
            if self.outputsize_x and self.outputsize_y:
                self.set_output_shape("OUTPUT", (self.outputsize_y, self.outputsize_x))
            elif self.outputsize:
                self.set_output_shape("OUTPUT", (self.outputsize,))
            else:
                raise ValueError("a receiver needs outputsize, or outputsize_x and "
                                 "outputsize_y")
        else:
            self.set_output_shape("OUTPUT", (0,))

    def init(self):
        yarp = self._yarp
        if self.type == "sender" and self.INPUT is None:
            raise ValueError("a sender needs its INPUT connected")
        yarp.Network.init()
        if not yarp.Network.checkNetwork():
            yarp.Network.fini()
            raise ValueError("no YARP name server answers: start yarpserver (and check "
                             "yarp conf)")
        name = self.port_name or "/ikaros/" + self.path.replace(".", "/")
        self._port = yarp.BufferedPortBottle()
        if not self._port.open(name):
            yarp.Network.fini()
            raise ValueError(f'cannot open the YARP port "{name}"')
        self._name = name
        if self.type == "receiver":
            self._port.setStrict(bool(self.receive_strict))
        if self.connect:
            pair = (self.connect, name) if self.type == "receiver" else (name, self.connect)
            if not yarp.Network.connect(*pair):
                self.warning(f"could not connect {pair[0]} to {pair[1]}")
        self._last = None

    def tick(self):
        if self.type == "sender":
            self._send()
        else:
            self._receive()

    def _send(self):
        values = self.INPUT.reshape(-1)
        if self.send_only_new_values and self._last is not None and \
                np.array_equal(values, self._last):
            self.YARP_ACTIVITY[0] = 0
            return
        bottle = self._port.prepare()
        bottle.clear()
        for v in values:
            bottle.addFloat64(float(v))
        self._port.write(bool(self.send_strict))
        self._last = values.copy()
        self.YARP_ACTIVITY[0] = 1

    def _receive(self):
        bottle = self._port.read(False)
        self.YARP_ACTIVITY[0] = bottle is not None
        if bottle is None:
            return
        flat = self.OUTPUT.reshape(-1)
        n = min(flat.size, bottle.size())
        for i in range(n):
            flat[i] = bottle.get(i).asFloat64()

    def stop(self):
        self._port.close()
        self._yarp.Network.fini()
