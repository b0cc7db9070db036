"""IPCServer: publishes its input every tick to IPCClient modules in other kernels."""
from ikaros.module import Input, Module, Parameter


class IPCServer(Module):
    """Publishes INPUT (the whole array, of any shape) every tick, with the tick number and
    a time stamp, to every IPCClient that connects to it (ZeroMQ publish/subscribe through
    pyzmq: ``pip install 'ikaros[links]'``). It listens on ``bind``:``port``, 127.0.0.1 by
    default (this machine only); an address that other machines can reach needs a shared
    ``key`` (or the environment variable IKAROS_LINK_KEY), and every message is then signed
    with HMAC-SHA256 so that a client with another key refuses it. Clients may come and go
    while the model runs; a tick's values reach the clients connected at the time. Unlike
    the Ikaros 2 class, which served up to 20 values over its own socket protocol, the
    address is set by parameters and the array keeps its shape (see docs/links.md)."""

    port = Parameter(9100, "the TCP port to listen on")
    bind = Parameter("127.0.0.1", "the address to listen on: 127.0.0.1 (this machine), an "
                     "interface's address, or * for all (which needs a key)")
    key = Parameter("", "the shared key that signs every message (empty: the environment "
                    "variable IKAROS_LINK_KEY, or no key on 127.0.0.1)")
    INPUT = Input("the array to publish")

    def init(self):
        from ikaros.hardware.link.endpoint import link_key
        from ikaros.hardware.link.peer import Publisher
        self._publisher = Publisher(self.bind, int(self.port), link_key(self.key))

    def tick(self):
        self._publisher.send({"tick": self.clock.tick, "clock": self.clock.time},
                             [self.INPUT])

    def stop(self):
        self._publisher.close()
