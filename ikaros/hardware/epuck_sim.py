"""A virtual e-puck on a pseudo-terminal, in a 2-D arena with walls and box obstacles.

It answers the commands of :mod:`ikaros.hardware.epuck`. The robot drives with its wheel
speeds (differential drive with the e-puck's wheel radius and axle length); a move that would
bring its body (radius 37 mm) into a wall or an obstacle is refused, so it stops there (it
may still turn) and ``contacts`` counts such collisions. Proximity sensors cast rays from the
rim in the e-puck's eight sensor directions and report ``60 + 3700 exp(-d / 12 mm)`` for the
distance d to the nearest surface within 10 cm (an approximation of the real sensors' curve;
about 1700 at 1 cm, 370 at 3 cm, 60 beyond 7 cm), minus the values stored by calibration
(K), plus optional Gaussian noise. The camera sees the arena through a simple ray caster
(walls grey, obstacles red, floor light, above the walls dark). As the firmware does, it
answers K with two lines (calibration started, finished) and takes a J asking for an image
that does not fit the robot's buffer (``epuck.IMAGE_PIXEL_BYTES``) without complaint, sending
40 x 40 colour images instead.

Time: with ``step`` > 0 every wheel-speed command (D) first advances the world by ``step``
seconds at the old speeds (lock step with a model that sends one per tick: deterministic);
with ``step`` = 0 the world follows the wall clock. Faults: ``silent`` (no replies) and
``corrupt`` (garbled replies); ``disconnect()`` unplugs it. ``commands`` keeps every command.
"""
from __future__ import annotations

import argparse
import math
import threading
import time

import numpy as np

from ikaros.hardware import DeviceError
from ikaros.hardware.epuck import (ACCELEROMETER_PER_G, ACCELEROMETER_ZERO, AXLE_LENGTH,
                                   IMAGE_COMMAND, MAX_STEPS_PER_SECOND, METRES_PER_STEP,
                                   PROXIMITY_ANGLES, RING_LEDS, ROBOT_RADIUS, encode_image,
                                   image_fits)
from ikaros.hardware.pty_device import PtyDevice

HELP = "an e-puck mobile robot in a 2-D arena with obstacles"
VERSION = "Version 1.2.2 (ikaros simulator)"
FAULTS = ("none", "silent", "corrupt")
SENSOR_RANGE = 0.10
SENSOR_BASE = 60.0
SENSOR_PEAK = 3700.0
SENSOR_DECAY = 0.012
CAMERA_FIELD = math.radians(56)
WALL_HEIGHT = 0.05               # metres; the camera sits at half of it
DEFAULT_OBSTACLES = "0.25,0.6,0.4,0.75;0.6,0.2,0.75,0.35"
_SUBSTEP = 0.005                 # seconds
FALLBACK_IMAGE = (40, 40)        # the colour image the firmware sends when one asked for does not fit


class Arena:
    """A ``width`` x ``height`` rectangle (metres, x right, y up) with walls on its edges and
    box obstacles given as (x0, y0, x1, y1) rows."""

    def __init__(self, width: float = 1.0, height: float = 1.0, obstacles=()):
        self.width, self.height = width, height
        self.obstacles = np.asarray(obstacles, np.float64).reshape(-1, 4)
        walls = [(0, 0, width, 0), (width, 0, width, height), (width, height, 0, height),
                 (0, height, 0, 0)]
        edges = []
        for x0, y0, x1, y1 in self.obstacles:
            a, b = (min(x0, x1), min(y0, y1)), (max(x0, x1), max(y0, y1))
            edges += [(a[0], a[1], b[0], a[1]), (b[0], a[1], b[0], b[1]),
                      (b[0], b[1], a[0], b[1]), (a[0], b[1], a[0], a[1])]
        self.segments = np.array(walls + edges, np.float64)
        self.is_obstacle = np.array([False] * 4 + [True] * len(edges))

    def cast(self, origin, angle: float, max_range: float) -> tuple[float, bool]:
        """Distance along the ray to the nearest segment (``max_range`` if none is closer)
        and whether it is an obstacle."""
        d = np.array([math.cos(angle), math.sin(angle)])
        p, e = self.segments[:, :2], self.segments[:, 2:] - self.segments[:, :2]
        denom = d[0] * e[:, 1] - d[1] * e[:, 0]
        w = p - np.asarray(origin)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (w[:, 0] * e[:, 1] - w[:, 1] * e[:, 0]) / denom
            s = (w[:, 0] * d[1] - w[:, 1] * d[0]) / denom
        hits = (np.abs(denom) > 1e-12) & (t >= 0) & (s >= 0) & (s <= 1) & (t < max_range)
        if not hits.any():
            return max_range, False
        k = int(np.argmin(np.where(hits, t, np.inf)))
        return float(t[k]), bool(self.is_obstacle[k])

    def blocked(self, point, radius: float) -> bool:
        """True when a disc of ``radius`` at ``point`` overlaps a wall or an obstacle."""
        x, y = point
        if not (0 < x < self.width and 0 < y < self.height):
            return True
        corners = self.obstacles[:, :2], self.obstacles[:, 2:]
        low, high = np.minimum(*corners), np.maximum(*corners)
        inside = np.all((low < point) & (np.asarray(point) < high), axis=1)
        return bool(inside.any()) or self.clearance(point) < radius

    def clearance(self, point) -> float:
        """Distance from a point to the nearest wall or obstacle edge."""
        p, e = self.segments[:, :2], self.segments[:, 2:] - self.segments[:, :2]
        w = np.asarray(point) - p
        s = np.clip(np.sum(w * e, axis=1) / np.sum(e * e, axis=1), 0.0, 1.0)
        return float(np.min(np.hypot(*(w - s[:, None] * e).T)))


class VirtualEpuck(PtyDevice):
    """The simulated robot. ``pose`` is (x, y, heading in radians counter-clockwise)."""

    name = "epuck"

    def __init__(self, arena: Arena | None = None, x: float = 0.2, y: float = 0.2,
                 heading: float = 0.0, step: float = 0.0, noise: float = 0.0, seed: int = 0,
                 fault: str = "none"):
        super().__init__()
        if fault not in FAULTS:
            raise ValueError(f"unknown fault '{fault}' (known: {', '.join(FAULTS)})")
        self.arena = arena or Arena(obstacles=parse_boxes(DEFAULT_OBSTACLES))
        if self.arena.blocked((x, y), ROBOT_RADIUS):
            raise ValueError(f"the start position ({x}, {y}) is inside a wall or an obstacle")
        self.pose = np.array([x, y, heading], np.float64)
        self.step, self.noise, self.fault = step, noise, fault
        self.rng = np.random.default_rng(seed)
        self.speeds = [0, 0]                       # steps/s
        self.encoders = np.zeros(2)                # steps
        self.leds = [0] * RING_LEDS
        self.body_led = self.front_led = self.sound = 0
        self.calibration = np.zeros(8)
        self.camera = (0, 40, 40, 8)               # mode, width, height, zoom
        self.contacts = 0
        self.distance = 0.0                        # metres travelled
        self.commands: list[str] = []
        self._blocked = False
        self._clock = time.monotonic()
        self._pending = bytearray()
        self.lock = threading.Lock()

    # --- the world -------------------------------------------------------------------------

    def advance(self, seconds: float) -> None:
        """Move the robot ``seconds`` forward at the present wheel speeds."""
        left, right = (s * METRES_PER_STEP for s in self.speeds)
        steps = max(1, math.ceil(seconds / _SUBSTEP - 1e-9))
        dt = seconds / steps
        for _ in range(steps):
            x, y, h = self.pose
            v, w = (left + right) / 2, (right - left) / AXLE_LENGTH
            nx, ny = x + v * dt * math.cos(h + w * dt / 2), y + v * dt * math.sin(h + w * dt / 2)
            blocked = v != 0 and self.arena.blocked((nx, ny), ROBOT_RADIUS)
            if blocked:
                nx, ny = x, y
                self.contacts += not self._blocked
            self._blocked = blocked
            self.distance += math.hypot(nx - x, ny - y)
            self.pose[:] = nx, ny, (h + w * dt + math.pi) % (2 * math.pi) - math.pi
        self.encoders += np.array(self.speeds, np.float64) * seconds

    def _sync_clock(self) -> None:
        now = time.monotonic()
        if self.step == 0:
            self.advance(now - self._clock)
        self._clock = now

    def raw_proximity(self) -> np.ndarray:
        x, y, h = self.pose
        values = []
        for angle in PROXIMITY_ANGLES:
            a = h + angle
            rim = (x + ROBOT_RADIUS * math.cos(a), y + ROBOT_RADIUS * math.sin(a))
            d, _ = self.arena.cast(rim, a, SENSOR_RANGE)
            near = SENSOR_PEAK * math.exp(-d / SENSOR_DECAY) if d < SENSOR_RANGE else 0.0
            values.append(SENSOR_BASE + near)
        return np.array(values)

    def proximity(self) -> list[int]:
        values = self.raw_proximity() - self.calibration
        if self.noise:
            values += self.rng.normal(0.0, self.noise, 8)
        return [int(round(v)) for v in np.maximum(values, 0.0)]

    def render(self) -> np.ndarray:
        """The camera image in 0..1 ((h, w) grey or (h, w, 3) colour)."""
        mode, width, height, _ = self.camera
        x, y, h = self.pose
        image = np.empty((height, width, 3))
        image[: height // 2] = (0.25, 0.25, 0.3)
        image[height // 2:] = (0.85, 0.85, 0.8)
        focal = (width / 2) / math.tan(CAMERA_FIELD / 2)
        for column in range(width):
            offset = math.atan2(width / 2 - column - 0.5, focal)
            d, obstacle = self.arena.cast((x, y), h + offset, 10.0)
            d *= math.cos(offset)
            half = min(height / 2, focal * (WALL_HEIGHT / 2) / max(d, 1e-3))
            top, bottom = int(round(height / 2 - half)), int(round(height / 2 + half))
            image[top:bottom, column] = (0.8, 0.25, 0.2) if obstacle else (0.55, 0.55, 0.6)
        return image.mean(axis=2) if mode == 0 else image

    # --- the protocol ------------------------------------------------------------------------

    def received(self, data: bytes) -> None:
        self._pending += data
        while True:
            if self._pending[:2] == IMAGE_COMMAND:
                del self._pending[:2]
                self._image()
                continue
            end = min((i for i in (self._pending.find(b"\r"), self._pending.find(b"\n"))
                       if i >= 0), default=-1)
            if end < 0:
                return
            line = bytes(self._pending[:end]).decode("ascii", "replace").strip()
            del self._pending[:end + 1]
            if line:
                self._command(line)

    def _command(self, line: str) -> None:
        self.commands.append(line)
        letter, *args = line.split(",")
        letter = letter.upper()
        try:
            values = [int(a) for a in args]
        except ValueError:
            self._reply("z")                     # the firmware's answer to what it does not know
            return
        with self.lock:
            reply = self._execute(letter, values)
        self._reply(reply)

    def _execute(self, letter: str, values: list[int]) -> str:
        if letter == "D" and len(values) == 2:
            if self.step > 0:
                self.advance(self.step)
            else:
                self._sync_clock()
            limit = MAX_STEPS_PER_SECOND
            self.speeds = [max(-limit, min(limit, v)) for v in values]
            return "d"
        self._sync_clock()
        if letter == "S":
            self.speeds = [0, 0]
            return "s"
        if letter == "N":
            return "n," + ",".join(map(str, self.proximity()))
        if letter == "Q":
            return "q," + ",".join(str(int(e)) for e in self.encoders)
        if letter == "E":
            return "e,{},{}".format(*self.speeds)
        if letter == "A":
            return f"a,{ACCELEROMETER_ZERO},{ACCELEROMETER_ZERO}," \
                   f"{ACCELEROMETER_ZERO + ACCELEROMETER_PER_G}"
        if letter == "U":
            level = 400 if self.sound else 20
            return f"u,{level},{level},{level}"
        if letter == "L" and len(values) == 2 and 0 <= values[0] <= RING_LEDS:
            numbers = range(RING_LEDS) if values[0] == RING_LEDS else [values[0]]
            for n in numbers:
                self.leds[n] = 1 - self.leds[n] if values[1] == 2 else int(values[1] != 0)
            return "l"
        if letter in ("B", "F") and len(values) == 1:
            setattr(self, "body_led" if letter == "B" else "front_led", int(values[0] != 0))
            return letter.lower()
        if letter == "T" and len(values) == 1:
            self.sound = values[0]
            return "t"
        if letter == "K":                       # two lines, as the firmware answers
            self.calibration = self.raw_proximity()
            return "k, Starting calibration - Remove any object in sensors range\r\n" \
                   "k, Calibration finished"
        if letter == "V":
            return "v," + VERSION
        if letter == "J" and len(values) == 4 and values[0] in (0, 1) and \
                values[1] > 0 and values[2] > 0:
            # an image that does not fit the buffer: the firmware switches format silently
            fits = image_fits(values[0] == 1, values[1], values[2])
            self.camera = tuple(values) if fits else (1, *FALLBACK_IMAGE, values[3])
            return "j"
        return "z"

    def _reply(self, text: str) -> None:
        if self.fault == "silent":
            return
        if self.fault == "corrupt":
            text = text.upper().replace("0", "#").replace("1", "?") + ",x"
        self.send(text.encode("ascii") + b"\r\n")

    def _image(self) -> None:
        with self.lock:
            self._sync_clock()
            mode, width, height, _ = self.camera
            data = bytes([mode, width, height]) + encode_image(self.render())
        if self.fault == "corrupt":
            data = bytes([7]) + data[1:]
        if self.fault != "silent":
            self.send(data)


def parse_boxes(text: str) -> list[tuple[float, ...]]:
    """Boxes ``"x0,y0,x1,y1;x0,y0,x1,y1"`` as rows of four numbers (``none`` or empty: none)."""
    boxes = []
    if text.strip().lower() == "none":
        return boxes
    for part in filter(None, (p.strip() for p in text.split(";"))):
        values = [float(v) for v in part.split(",")]
        if len(values) != 4:
            raise ValueError(f"an obstacle needs x0,y0,x1,y1, not '{part}'")
        boxes.append(tuple(values))
    return boxes


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--width", type=float, default=1.0, help="arena width, metres")
    parser.add_argument("--height", type=float, default=1.0, help="arena height, metres")
    parser.add_argument("--obstacles", default=DEFAULT_OBSTACLES,
                        help="box obstacles x0,y0,x1,y1;... in metres (none: no obstacles)")
    parser.add_argument("--x", type=float, default=0.2, help="start x, metres")
    parser.add_argument("--y", type=float, default=0.2, help="start y, metres")
    parser.add_argument("--heading", type=float, default=0.0,
                        help="start heading, degrees counter-clockwise from the x axis")
    parser.add_argument("--step", type=float, default=0.0,
                        help="seconds simulated per wheel-speed command (0: real time)")
    parser.add_argument("--noise", type=float, default=0.0,
                        help="standard deviation of proximity noise, counts")
    parser.add_argument("--seed", type=int, default=0, help="seed of the noise")
    parser.add_argument("--fault", choices=FAULTS, default="none",
                        help="inject a fault: silent (no replies), corrupt (garbled replies)")


def start(options: argparse.Namespace) -> VirtualEpuck:
    try:
        arena = Arena(options.width, options.height, parse_boxes(options.obstacles))
        robot = VirtualEpuck(arena, options.x, options.y, math.radians(options.heading),
                             options.step, options.noise, options.seed, options.fault)
    except ValueError as error:
        raise DeviceError(f"e-puck simulator: {error}") from None
    return robot.start()
