"""LaunchpadLED: colours on the pads of a Novation Launchpad X."""
import time

import numpy as np

from ikaros.hardware import DeviceError, launchpad, midi
from ikaros.module import Input, Module, Output, Parameter

RETRY_SECONDS = 1.0             # how often a missing Launchpad is looked for again


class LaunchpadLED(Module):
    """Lights the pads of a Novation Launchpad X (Ikaros 3's class, written here from its
    interface and Novation's Launchpad X Programmer's reference manual). Row k of COLOR is
    the red, green and blue (0..1) of pad k, the pads counted in rows of ``layout_width``
    from the top left (an 8 × 8 grid: 64 rows; with a width of 9 the ninth column is the
    scene-launch buttons; rows below the eighth are left out). The colours are multiplied by
    ``playing_brightness`` while any element of PLAYING is above 0 (or PLAYING is not
    connected), else by ``idle_brightness``, and sent as 0..127 levels in one LED lighting
    System Exclusive message of RGB colour specs, only for the pads whose colour changed
    (LAST_UPDATE_COUNT of them on this tick). When it starts it switches the Launchpad to
    Programmer mode (``programmer_mode``); when the run ends it turns the pads it lit off
    (``clear_on_stop``) and switches back to Live mode (``restore_live_mode``). The
    Launchpad is the first MIDI output whose name contains ``destination_name`` (the real
    device's input is "LPX MIDI In"; ``sim:launchpad`` is the simulated one, see
    docs/robots.md); DESTINATION_COUNT is the number of MIDI outputs and CONNECTED is 1
    while it is open. A Launchpad that is missing, or goes away, is looked for again every
    second (and sent every colour when found), and the run goes on. Real ports need mido
    and python-rtmidi (``pip install 'ikaros[midi]'``)."""

    destination_name = Parameter("LPX MIDI In", "the MIDI output whose name contains this "
                                 "(sim:launchpad: the simulated Launchpad X)")
    layout_width = Parameter(8, "pads per row of COLOR", type="int", range=(1, None))
    idle_brightness = Parameter(0.2, "the colours are multiplied by this while nothing plays",
                                range=(0, 1))
    playing_brightness = Parameter(1.0, "the colours are multiplied by this while PLAYING",
                                   range=(0, 1))
    programmer_mode = Parameter(True, "switch the Launchpad to Programmer mode at the start")
    clear_on_stop = Parameter(True, "turn the pads off when the run ends")
    restore_live_mode = Parameter(True, "switch the Launchpad back to Live mode when the run "
                                  "ends")
    COLOR = Input("red, green and blue (0..1) of each pad, one row per pad")
    PLAYING = Input("when connected, the colours are at playing_brightness while any element "
                    "is above 0 and at idle_brightness otherwise", optional=True)
    CONNECTED = Output("1 while the Launchpad is open", size="1")
    DESTINATION_COUNT = Output("the number of MIDI outputs", size="1")
    LAST_UPDATE_COUNT = Output("the number of pads sent a colour on this tick", size="1")

    def configure(self):
        midi.require_ports(self.destination_name)

    def init(self):
        if self.COLOR.size % 3:
            raise ValueError(f"COLOR has {self.COLOR.size} elements: it needs three (red, "
                             f"green, blue) per pad")
        pads = self.COLOR.size // 3
        width = self.layout_width
        self._leds = np.array([launchpad.pad_number(k // width, k % width)
                               if k // width < launchpad.GRID and k % width <= launchpad.GRID
                               else -1 for k in range(pads)])
        self._port = None
        self._sent: dict[int, tuple] = {}
        self._next_try = 0.0
        self._connect()

    def _connect(self):
        self._next_try = time.monotonic() + RETRY_SECONDS
        ports = midi.open_wanted(self.destination_name, True, index=0, warn=self._warn)
        self._port = ports[0] if ports else None
        self._sent = {}
        if self._port is not None and self.programmer_mode:
            try:
                self._port.send(launchpad.mode_switch(programmer=True))
            except DeviceError as e:
                self._warn(str(e))
                self._drop()
        self.DESTINATION_COUNT[0] = len(midi.port_names(output=True))
        self.CONNECTED[0] = float(self._port is not None)

    def _warn(self, message: str):
        self.warning(f"{message}; trying again every {RETRY_SECONDS:g} s")

    def tick(self):
        if self._port is None and time.monotonic() >= self._next_try:
            self._connect()
        self.LAST_UPDATE_COUNT[0] = 0
        if self._port is None:
            return
        playing = self.PLAYING is None or bool(np.any(self.PLAYING > 0))
        brightness = self.playing_brightness if playing else self.idle_brightness
        rgb = np.nan_to_num(self.COLOR.reshape(-1, 3), nan=0.0)
        levels = np.rint(np.clip(rgb * brightness, 0, 1) * launchpad.LEVELS).astype(int)
        changed = {int(led): tuple(int(v) for v in level)
                   for led, level in zip(self._leds, levels)
                   if led >= 0 and self._sent.get(int(led)) != tuple(level)}
        if changed:
            try:
                self._port.send(launchpad.led_lighting(changed))
            except DeviceError as e:
                self._warn(str(e))
                self._drop()
                return
            self._sent.update(changed)
        self.LAST_UPDATE_COUNT[0] = len(changed)
        self.CONNECTED[0] = 1

    def _drop(self):
        if self._port is not None:
            self._port.close()
        self._port = None
        self.CONNECTED[0] = 0

    def stop(self):
        port = getattr(self, "_port", None)
        if port is None:
            return
        try:
            if self.clear_on_stop:
                lit = {led: (0, 0, 0) for led, colour in self._sent.items() if any(colour)}
                if lit:
                    port.send(launchpad.led_lighting(lit))
            if self.restore_live_mode:
                port.send(launchpad.mode_switch(programmer=False))
        except DeviceError as e:
            self.warning(str(e))
        self._drop()
