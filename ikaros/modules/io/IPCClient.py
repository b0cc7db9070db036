"""IPCClient: receives the arrays an IPCServer in another kernel publishes."""
import time

import numpy as np

from ikaros.module import Module, Output, Parameter


class IPCClient(Module):
    """Receives what an IPCServer publishes (``host``:``port``; pyzmq: ``pip install
    'ikaros[links]'``). OUTPUT has the shape ``shape`` (20 by default, as in Ikaros 2; a
    list such as ``480, 640`` gives any rank); a message of the same number of elements fills
    it in order, a smaller one fills its start and zeroes the rest, a larger one is cut (with
    a warning once).

    Every tick the client takes new values: with ``mode="latest"`` the newest message that
    has arrived (older ones are dropped, what a robot wants), with ``mode="each"`` the next
    message in order (every tick of the server, for two kernels that run in step). When no
    new message has arrived it waits up to ``time_out_in_ms`` for one (0: not at all); if
    none comes it goes on with the last values and TIME_OUT is 1 for that tick. TICK and
    TIME_STAMP are the server's tick number and kernel time of the values, LATENCY the
    seconds from sending to receiving.

    A lost server (stopped, killed, or silent for 2 s) is reported as a warning and the run
    goes on; the client reconnects by itself and reports when the server is back. A server on
    another machine needs a shared ``key`` (or the environment variable IKAROS_LINK_KEY);
    messages signed with another key, or not signed when one is expected, are refused and
    reported once."""

    host = Parameter("127.0.0.1", "the address of the IPCServer")
    port = Parameter(9100, "the TCP port of the IPCServer")
    key = Parameter("", "the shared key the server signs with (empty: the environment "
                    "variable IKAROS_LINK_KEY, or no key on 127.0.0.1)")
    shape = Parameter("20", "the shape of OUTPUT: a number, or sizes separated by commas "
                      "(rows, columns, ...)")
    time_out_in_ms = Parameter(0.0, "how long a tick waits for new values before it goes on "
                               "with the last ones and sets TIME_OUT (0: no wait)")
    mode = Parameter("latest", "latest: the newest values each tick; each: every message "
                     "in order, one per tick", options="latest,each")
    OUTPUT = Output("the received values")
    TIME_OUT = Output("1 on a tick when no new values came in time, else 0", size=1)
    TICK = Output("the server's tick of the values in OUTPUT (-1 before any)", size=1)
    TIME_STAMP = Output("the server's kernel time (seconds) of the values in OUTPUT", size=1)
    LATENCY = Output("seconds from the server's sending to this client's receiving", size=1)

    def configure(self):
        try:
            shape = tuple(int(s) for s in str(self.shape).replace(";", ",").split(",")
                          if s.strip())
            if not shape or min(shape) < 1:
                raise ValueError
        except ValueError:
            raise ValueError(f'shape="{self.shape}" must be one or more whole numbers >= 1 '
                             f'separated by commas') from None
        self.set_output_shape("OUTPUT", shape)

    def init(self):
        from ikaros.hardware.link.endpoint import link_key
        from ikaros.hardware.link.peer import Subscriber
        self._link = Subscriber(self.host, int(self.port), link_key(self.key))
        self._reported: set[str] = set()
        self._was_connected = False
        self.TICK[0] = -1

    def tick(self):
        from ikaros.hardware.link.wire import LinkError
        self._report_connection()
        try:
            message = self._link.receive(max(0.0, self.time_out_in_ms) / 1000,
                                         newest=self.mode == "latest")
        except LinkError as e:
            self._once(str(e), self.error)
            message = None
        self._report_connection()
        self.TIME_OUT[0] = message is None
        if message is not None:
            self._take(*message)

    def _take(self, header, arrays):
        received = time.time()
        data = arrays[0] if arrays else np.zeros(0, np.float32)
        flat = self.OUTPUT.reshape(-1)
        n = min(flat.size, data.size)
        if data.size > flat.size:
            self._once(f"the server sends {data.size} values but OUTPUT has {flat.size} "
                       f"(shape={self.shape}): the rest are left out", self.warning)
        flat[:n] = data.reshape(-1)[:n]
        flat[n:] = 0
        self.TICK[0] = header.get("tick", -1)
        self.TIME_STAMP[0] = header.get("clock", 0.0)
        self.LATENCY[0] = received - header.get("time", received)

    def _report_connection(self):
        for event in self._link.events():
            if event == "connected" and self._was_connected:
                self.warning(f"reconnected to the IPCServer at {self._link.address}")
            elif event == "connected":
                self._was_connected = True
            elif event == "disconnected":
                self.warning(f"lost the IPCServer at {self._link.address}: going on with "
                             f"the last values and reconnecting")

    def _once(self, message, report):
        if message not in self._reported:
            self._reported.add(message)
            report(message)

    def stop(self):
        self._link.close()
