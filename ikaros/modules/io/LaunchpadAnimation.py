"""LaunchpadAnimation: a moving rainbow with ripples and sparkles for an 8 × 8 pad grid."""
import numpy as np

from ikaros.hardware import launchpad
from ikaros.module import Input, Module, Output, Parameter

GRID = launchpad.GRID
RIPPLE_SPEED = 6.0          # pads per second (times speed) that a ripple's ring travels
RIPPLE_LIFE = 1.0           # seconds in which a ripple fades to 1/e
SPARKLE_SHARE = 0.05        # the share of pads that sparkle in a frame at sparkle 1


class LaunchpadAnimation(Module):
    """A procedural animation for the 64 pads of a Launchpad (Ikaros 3's class, written
    here from its interface; the animation is this project's own): COLOR has a row of red,
    green and blue (0..1) per pad, in rows of 8 from the top left, for LaunchpadLED. A new
    frame is made when the model's time has moved on by 1/``frame_rate`` s or more (COLOR
    is kept in between); at time t, for the pad in row r and column c (from 0 at the top
    left), the hue is frac(0.1·speed·t + (r + c)/16) (a rainbow drifting across the grid),
    the saturation ``saturation`` and the value brightness·(0.35 + 0.65·w) with
    w = 0.5 + 0.5·sin 2π(0.25·speed·t − r/8) (a wave moving down). A press (TRIG rising
    above 0, or EVENT_COUNT growing) starts a ripple at KEY's pad (a Launchpad Programmer-
    layout number, 11 ... 88; any other key: the middle of the grid): a ring of radius
    6·speed·(t − t0) pads that adds reactivity·exp(−(d − radius)²)·exp(−(t − t0)) to the
    value of a pad at distance d and whitens it as much (only the last press ripples). In
    each frame a pad sparkles (white at ``brightness``) when frac(43758.5453·sin(12.9898·k
    + 78.233·f)) < 0.05·sparkle for pad k and frame f, which is the same in every run.
    The colour is the HSV colour turned into RGB."""

    speed = Parameter(1.0, "how fast the rainbow, the wave and the ripples move")
    brightness = Parameter(1.0, "the brightest value", range=(0, 1))
    saturation = Parameter(0.9, "the saturation of the rainbow", range=(0, 1))
    sparkle = Parameter(0.65, "how many pads sparkle (1: 5 % of the pads in each frame)",
                        range=(0, None))
    reactivity = Parameter(1.0, "the strength of the ripple a press starts", range=(0, None))
    frame_rate = Parameter(30.0, "frames per second of model time", range=(0, None),
                           finite=True)
    KEY = Input("the key last pressed (a Programmer-layout pad number)", optional=True,
                size="1")
    TRIG = Input("a rise above 0 starts a ripple", optional=True, size="1")
    EVENT_COUNT = Input("a rise starts a ripple", optional=True, size="1")
    COLOR = Output("red, green and blue (0..1) of each of the 64 pads", shape="64, 3")

    def init(self):
        rows, columns = np.divmod(np.arange(GRID * GRID), GRID)
        self._rows, self._columns = rows.astype(np.float64), columns.astype(np.float64)
        self._frame = 0
        self._last_frame_time = None
        self._trig = 0.0
        self._events = None
        self._ripple = None             # (time, row, column) of the last press

    def tick(self):
        t = self.clock.time
        self._take_presses(t)
        due = self._last_frame_time is None or self.frame_rate <= 0 or \
            t - self._last_frame_time >= 1.0 / self.frame_rate - 1e-9
        if due:
            self._last_frame_time = t
            self.COLOR[...] = self.frame(t, self._frame)
            self._frame += 1

    def _take_presses(self, t: float):
        pressed = False
        if self.TRIG is not None:
            trig = float(self.TRIG.flat[0])
            pressed = trig > 0 >= self._trig
            self._trig = trig
        if self.EVENT_COUNT is not None:
            count = float(self.EVENT_COUNT.flat[0])
            pressed |= self._events is not None and count > self._events
            self._events = count
        if pressed:
            key = int(self.KEY.flat[0]) if self.KEY is not None else 0
            position = launchpad.pad_position(key) or ((GRID - 1) / 2, (GRID - 1) / 2)
            self._ripple = (t, *position)

    def frame(self, t: float, number: int) -> np.ndarray:
        """The colours (64, 3) at time t in frame ``number``."""
        speed, r, c = self.speed, self._rows, self._columns
        hue = np.mod(0.1 * speed * t + (r + c) / 16, 1.0)
        wave = 0.5 + 0.5 * np.sin(2 * np.pi * (0.25 * speed * t - r / 8))
        value = self.brightness * (0.35 + 0.65 * wave)
        saturation = np.full(len(r), float(self.saturation))
        if self._ripple is not None:
            t0, r0, c0 = self._ripple
            age = max(0.0, t - t0)
            distance = np.hypot(r - r0, c - c0)
            ring = self.reactivity * np.exp(-(distance - RIPPLE_SPEED * speed * age) ** 2) \
                * np.exp(-age / RIPPLE_LIFE)
            value = np.minimum(1.0, value + self.brightness * ring)
            saturation *= 1 - np.minimum(1.0, ring)
        k = np.arange(len(r))
        noise = np.mod(43758.5453 * np.sin(12.9898 * k + 78.233 * number), 1.0)
        sparkles = noise < SPARKLE_SHARE * self.sparkle
        value[sparkles] = self.brightness
        saturation[sparkles] = 0.0
        return hsv_to_rgb(hue, saturation, np.clip(value, 0.0, 1.0))


def hsv_to_rgb(h: np.ndarray, s: np.ndarray, v: np.ndarray) -> np.ndarray:
    """HSV colours (each 0..1) as RGB, one row per colour."""
    sector = np.floor(h * 6).astype(int) % 6
    f = h * 6 - np.floor(h * 6)
    p, q, t = v * (1 - s), v * (1 - f * s), v * (1 - (1 - f) * s)
    choices = [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)]
    rgb = np.empty((len(h), 3))
    for n, (red, green, blue) in enumerate(choices):
        chosen = sector == n
        rgb[chosen] = np.stack([red[chosen], green[chosen], blue[chosen]], axis=1)
    return rgb
