"""FadeCandy: NeoPixel LED strips through a FadeCandy server (Open Pixel Control over TCP)."""
import shutil
import socket
import subprocess
import time

import numpy as np

from ikaros.module import Input, Module, Parameter

_SERVER_START_SECONDS = 3.0
# The Epi's LEDs (Ikaros 3's inputs): the strip of the FadeCandy board each is on (64 pixels a
# strip on OPC channel 0, fcserver's built-in map) and its pixels when an input gives one colour
EPI_LEDS = {"LEFT_EYE": (0, 12), "RIGHT_EYE": (1, 12), "MOUTH_HIGH": (2, 8), "MOUTH_LOW": (3, 8)}
STRIP = 64


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
    (pixels 0..511, 64 a strip): use channel 0 unless its configuration maps others.
    The Epi's LEDs, as Ikaros 3 names them: LEFT_EYE and RIGHT_EYE (the iris rings) and
    MOUTH_HIGH and MOUTH_LOW (the two rows of the mouth), each 3 values (one colour, red, green,
    blue in 0..1, for all its pixels: 12 an eye, 8 a mouth row) or a 3 × N matrix (a row per
    colour, a column per pixel, N up to 64); they are sent in one OPC message on channel 0 with
    the left eye on the board's strip 0, the right eye on strip 1 and the mouth rows on
    strips 2 and 3 (pixels 0, 64, 128 and 192). In an Ikaros 3 file the four are required, as
    there; in an Ikaros 2 file they are optional. ``simulate`` sends everything to a
    simulated OPC server in this process instead (the same as ``address="sim:opc"``): nothing
    is opened. This project's reading: Ikaros 3 gives these inputs and ``simulate`` only; the
    colour format, the pixel counts and the strips are this project's. Differences from
    Ikaros 2: ``address`` is new (Ikaros 2 always used 127.0.0.1:7890); the program is the
    parameter ``server``, default fcserver (``command`` is a reserved name in this module API;
    a ``command`` attribute in a model is still read; Ikaros 2's default was fcserver-osx)."""

    server = Parameter("fcserver", "the FadeCandy server program, started when "
                       "start_server is on and it is installed (Ikaros 2: command)")
    start_server = Parameter(True, "start the server program (when installed) at the start "
                             "and stop it at the end")
    address = Parameter("127.0.0.1:7890", "host:port of the OPC server, or sim:opc for the "
                        "simulated server")
    simulate = Parameter(False, "send to a simulated OPC server in this process (nothing is opened)")

    LEFT_EYE = Input("the left eye's colour (3 values) or pixels (3 × N), 0..1 (required in an Ikaros 3 file)",
                     optional=True)
    RIGHT_EYE = Input("the right eye's colour or pixels, 0..1 (required in an Ikaros 3 file)", optional=True)
    MOUTH_HIGH = Input("the mouth's upper row: colour or pixels, 0..1 (required in an Ikaros 3 file)",
                       optional=True)
    MOUTH_LOW = Input("the mouth's lower row: colour or pixels, 0..1 (required in an Ikaros 3 file)",
                      optional=True)

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
        self._epi = self._epi_leds()
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
        if self.simulate or is_simulated(self.address):
            self._simulator = start_from_device_string(self.address if is_simulated(self.address) else "sim:opc")
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
        self._send_epi()

    def _epi_leds(self) -> list[tuple[str, int, int]]:
        """The Epi's LED inputs that are connected: (name, first pixel, pixels)."""
        missing = [name for name in EPI_LEDS if not self.connected(name)]
        if self.dialect == "3" and missing:
            raise ValueError(f"the input {', '.join(missing)} is not connected (required in an Ikaros 3 file)")
        leds = []
        for name, (strip, pixels) in EPI_LEDS.items():
            value = getattr(self, name)
            if value is None:
                continue
            if value.size != 3 and (value.ndim != 2 or value.shape[0] != 3 or value.shape[1] > STRIP):
                raise ValueError(f"{name} has the shape {value.shape}: give one colour (3 values) or a row "
                                 f"per colour and a column per pixel (3 × N, N up to {STRIP})")
            leds.append((name, strip * STRIP, pixels if value.size == 3 else value.shape[1]))
        return leds

    def _send_epi(self) -> None:
        """The Epi's LEDs in one message on OPC channel 0, once every input has a value."""
        if not self._epi or not all(self.input_ready(name).all() for name, _, _ in self._epi):
            return
        rgb = np.zeros((max(start + count for _, start, count in self._epi), 3), np.float32)
        for name, start, count in self._epi:
            value = getattr(self, name)
            rgb[start:start + count] = value.reshape(1, 3) if value.size == 3 else value.T
        self._client.set_pixels(0, rgb)

    def _lights_off(self):
        """Every pixel of every channel black (called by stop and at exit)."""
        if self._client is not None:
            for number, size, _, _ in self._inputs:
                self._client.set_pixels(number, np.zeros((size, 3)))
            if self._epi:
                self._client.set_pixels(0, np.zeros((max(s + c for _, s, c in self._epi), 3)))

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
