"""FadeCandy: NeoPixel LED strips through a FadeCandy server (Open Pixel Control over TCP)."""
import shutil
import socket
import subprocess
import time

import numpy as np

from ikaros.module import Module, Parameter

_SERVER_START_SECONDS = 3.0


class FadeCandy(Module):
    """Sends LED colours to a FadeCandy board through its server (fcserver) with the Open Pixel
    Control protocol over TCP. Each child element ``<channel name="EYES" channel="0"
    size="12"/>`` gives the inputs EYES_RED, EYES_GREEN and EYES_BLUE (optional, 0 when
    unconnected), each with at least ``size`` values in 0..1, one per pixel; every tick one OPC
    message per channel sets its pixels (colours clipped to 0..1 and scaled to 0..255). Nothing
    is sent before the first tick, nor to a channel before its connected inputs have received
    values from their sources (``Module.input_ready``); when the run ends every channel is set to black (LEDs off),
    as at interpreter exit. With ``start_server`` the program ``server`` is started (and stopped
    at the end) when it is installed; otherwise, or when it is not found, a server already
    running at ``address`` is used. ``address="sim:opc"`` runs a simulated OPC server in this
    process (see docs/robots.md). A server that cannot be reached, or that goes away, stops the
    run with an error naming its address. fcserver's built-in map takes OPC channel 0 only
    (pixels 0..511, 64 a strip): use channel 0 unless its configuration maps others. Differences from Ikaros 2: ``address`` is new (Ikaros
    2 always used 127.0.0.1:7890); the program is the parameter ``server``, default fcserver
    (``command`` is a reserved name in this module API; a ``command`` attribute in a model is
    still read; Ikaros 2's default was fcserver-osx)."""

    server = Parameter("fcserver", "the FadeCandy server program, started when "
                       "start_server is on and it is installed (Ikaros 2: command)")
    start_server = Parameter(True, "start the server program (when installed) at the start "
                             "and stop it at the end")
    address = Parameter("127.0.0.1:7890", "host:port of the OPC server, or sim:opc for the "
                        "simulated server")

    def configure(self):
        if self.element is not None and "command" in self.element.attrs:
            self.server = self.element.get("command")      # the Ikaros 2 name (reserved here)
        self._channels = []
        for element in (self.element.elements("channel") if self.element is not None else []):
            where = f"line {element.line}" if element.line else "a <channel> element"
            name = element.get("name")
            try:
                number, size = int(element.get("channel", "")), int(element.get("size", ""))
            except ValueError:
                raise ValueError(f"<channel> at {where} needs whole-number channel and size "
                                 "attributes") from None
            if not name or not 0 <= number <= 255 or size < 1:
                raise ValueError(f"<channel> at {where} needs a name, a channel in 0..255 and "
                                 "a size of at least 1")
            self._channels.append((name, number, size))
            for colour in ("RED", "GREEN", "BLUE"):
                self.add_input(f"{name}_{colour}", optional=True,
                               description=f"{colour.lower()} of the {size} pixels of {name}, "
                                           "0..1")

    def init(self):
        from ikaros.hardware.opc import OPCClient
        self._client = self._server = self._simulator = self._exit_key = None
        self._inputs = []
        for name, number, size in self._channels:
            colours = []
            for colour in ("RED", "GREEN", "BLUE"):
                value = getattr(self, f"{name}_{colour}")
                if value is not None and value.size < size:
                    raise ValueError(f"{name}_{colour} has {value.size} values; channel {name} "
                                     f"has {size} pixels")
                colours.append(value)
            connected = [f"{name}_{c}" for c, v in zip(("RED", "GREEN", "BLUE"), colours) if v is not None]
            self._inputs.append((number, size, colours, connected))
        try:
            address = self._start_server()
            self._client = OPCClient(address)
        except Exception:
            self.stop()
            raise
        from ikaros.hardware import safety
        self._exit_key = safety.on_exit(f"the LEDs at {address}", self._lights_off)

    def _start_server(self) -> str:
        from ikaros.hardware.simulators import is_simulated, start_from_device_string
        if is_simulated(self.address):
            self._simulator = start_from_device_string(self.address)
            return self._simulator.path
        if self.start_server:
            program = shutil.which(self.server)
            if program is None:
                self.warning(f"start_server: the program '{self.server}' is not installed; "
                             f"using a server already running at {self.address}")
            elif not _listening(self.address):
                self._server = subprocess.Popen([program], stdout=subprocess.DEVNULL,
                                                stderr=subprocess.DEVNULL)
                deadline = time.monotonic() + _SERVER_START_SECONDS
                while not _listening(self.address) and time.monotonic() < deadline:
                    time.sleep(0.05)
        return self.address

    def tick(self):
        for number, size, colours, connected in self._inputs:
            if not all(self.input_ready(name)[:size].all() for name in connected):
                continue                        # no value from the source yet: leave it as it is
            rgb = np.zeros((size, 3), np.float32)
            for k, value in enumerate(colours):
                if value is not None:
                    rgb[:, k] = value.reshape(-1)[:size]
            self._client.set_pixels(number, rgb)

    def _lights_off(self):
        """Every pixel of every channel black (called by stop and at exit)."""
        if self._client is not None:
            for number, size, _, _ in self._inputs:
                self._client.set_pixels(number, np.zeros((size, 3)))

    def stop(self):
        from ikaros.hardware import DeviceError, safety
        try:
            self._lights_off()
        except DeviceError as error:
            self.error(f"the LEDs could not be turned off: {error}")
        finally:
            safety.cancel(self._exit_key)
            client, self._client = self._client, None
            if client is not None:
                client.close()
            if self._server is not None:
                self._server.terminate()
                try:
                    self._server.wait(timeout=2.0)
                except subprocess.TimeoutExpired:
                    self._server.kill()
                self._server = None
            if self._simulator is not None:
                self._simulator.stop()
                self._simulator = None


def _listening(address: str) -> bool:
    from ikaros.hardware.opc import split_address
    try:
        with socket.create_connection(split_address(address), timeout=0.2):
            return True
    except OSError:
        return False
