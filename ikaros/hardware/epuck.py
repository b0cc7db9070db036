"""The e-puck mobile robot: its serial command protocol (the ASCII commands of the e-puck's
standard firmware, over Bluetooth serial or a cable) and a driver.

A command is a capital letter with comma-separated arguments, ended by a carriage return;
the robot answers with the same letter in lower case and the values, ended by ``\\r\\n``::

    D,500,-500\\r   ->  d\\r\\n                 wheel speeds, steps/s (-1000..1000)
    N\\r            ->  n,12,8,...,35\\r\\n      the 8 proximity sensors (IR0..IR7)
    Q\\r            ->  q,1200,-340\\r\\n        the wheel encoders (left, right), steps
    A\\r            ->  a,2048,2048,2848\\r\\n   the accelerometer (x, y, z), raw counts
    U\\r            ->  u,20,31,18\\r\\n         the three microphones' amplitudes
    L,3,1\\r        ->  l\\r\\n                 ring LED 3 on (0 off, 1 on, 2 toggle)
    B,1\\r / F,1\\r  ->  b\\r\\n / f\\r\\n         body LED / front LED
    T,2\\r          ->  t\\r\\n                 play sound 2 (0 stops)
    S\\r            ->  s\\r\\n                 stop the motors
    K\\r            ->  k, Starting calibration - Remove any object in sensors range\\r\\n
                      k, Calibration finished\\r\\n   (seconds later) calibrate the
                                              proximity sensors
    V\\r            ->  v,Version ...\\r\\n      the firmware version
    J,1,32,32,8\\r  ->  j\\r\\n                 camera mode (0 grey, 1 colour), width, height, zoom

The camera image is binary: the bytes 0xB7 0x00 (the negative of "I", then the end of the
binary commands) return the mode, width and height bytes and then the pixels: one grey byte
each, or two bytes of RGB565 (big-endian) each in colour mode. The pixels may take at most
52·39·2 = 4056 bytes (GCtronic, "Advanced sercom protocol", command J; the e-puck2's buffer
is 4056 + 3 + 80 = 4139 bytes): a J command asking for more is answered ``j`` all the same,
and the firmware sends another format (80 x 60 grey comes back as 40 x 40 RGB565).

The wheels are stepper motors of 1000 steps a turn on wheels of 20.5 mm radius, 53 mm apart,
so 1000 steps/s is about 12.9 cm/s.
"""
from __future__ import annotations

import math

import numpy as np

from ikaros.hardware import DeviceError
from ikaros.hardware.serial_port import SerialDevice

DEFAULT_BAUD_RATE = 115200
MAX_STEPS_PER_SECOND = 1000
STEPS_PER_TURN = 1000
WHEEL_RADIUS = 0.0205            # metres
AXLE_LENGTH = 0.053              # metres between the wheels
ROBOT_RADIUS = 0.037             # metres
METRES_PER_STEP = 2 * math.pi * WHEEL_RADIUS / STEPS_PER_TURN
PROXIMITY_ANGLES = np.radians([-10, -45, -90, -150, 150, 90, 45, 10])   # IR0..IR7, left > 0
ACCELEROMETER_ZERO = 2048        # raw counts at 0 g
ACCELEROMETER_PER_G = 800        # raw counts per g
RING_LEDS = 8
_MODES = {0: "grey", 1: "colour"}
IMAGE_COMMAND = bytes([256 - ord("I"), 0])
IMAGE_HEADER = 3                 # mode, width, height
IMAGE_PIXEL_BYTES = 52 * 39 * 2  # "The total image size must not exceed 4056 bytes" (command J)
IMAGE_BUFFER = IMAGE_PIXEL_BYTES + IMAGE_HEADER + 80   # the robot's image buffer (e-puck2)
CALIBRATION_SECONDS = 10.0       # the firmware's K answers its second line when it is done


def image_bytes(colour: bool, width: int, height: int) -> int:
    """Bytes of a camera image's pixels: one a grey pixel, two a colour one."""
    return width * height * (2 if colour else 1)


def image_fits(colour: bool, width: int, height: int) -> bool:
    """Whether the robot can send such an image (at most ``IMAGE_PIXEL_BYTES`` of pixels)."""
    return width > 0 and height > 0 and image_bytes(colour, width, height) <= IMAGE_PIXEL_BYTES


class NotAnswering(DeviceError):
    """The robot does not answer at all (gone, switched off, out of Bluetooth range)."""


def command_line(letter: str, *args: int) -> bytes:
    """An ASCII command: ``command_line("D", 500, -500) == b"D,500,-500\\r"``."""
    return (",".join([letter, *(str(int(a)) for a in args)]) + "\r").encode("ascii")


def parse_reply(letter: str, line: bytes) -> list[int]:
    """The values of a reply line to command ``letter``; ValueError when it is not one."""
    text = line.decode("ascii", "replace").strip()
    parts = text.split(",")
    if parts[0] != letter.lower():
        raise ValueError(f"'{text[:40]}' is not a reply to {letter}")
    try:
        return [int(p) for p in parts[1:]]
    except ValueError:
        raise ValueError(f"'{text[:40]}' has a value that is not a whole number") from None


def decode_image(data: bytes, mode: int, width: int, height: int) -> np.ndarray:
    """The camera pixels in 0..1: (height, width) grey or (height, width, 3) colour."""
    if mode == 0:
        return np.frombuffer(data, np.uint8).reshape(height, width) / 255.0
    words = np.frombuffer(data, ">u2").reshape(height, width).astype(np.uint32)
    red, green, blue = words >> 11, (words >> 5) & 0x3F, words & 0x1F
    return np.stack([red / 31.0, green / 63.0, blue / 31.0], axis=-1)


def encode_image(pixels: np.ndarray) -> bytes:
    """Pixels in 0..1 ((h, w) grey or (h, w, 3) colour) as the camera sends them."""
    pixels = np.clip(pixels, 0.0, 1.0)
    if pixels.ndim == 2:
        return np.rint(pixels * 255).astype(np.uint8).tobytes()
    r, g, b = (np.rint(pixels[..., k] * m).astype(np.uint16) for k, m in
               ((0, 31), (1, 63), (2, 31)))
    return ((r << 11) | (g << 5) | b).astype(">u2").tobytes()


def acceleration_figures(raw) -> tuple[float, float, float]:
    """(acceleration in g, orientation in degrees, inclination in degrees) from raw counts:
    the magnitude, the direction of the horizontal part (0..360, counter-clockwise from the
    robot's forward x axis) and the angle between the robot's z axis and the acceleration."""
    x, y, z = ((v - ACCELEROMETER_ZERO) / ACCELEROMETER_PER_G for v in raw)
    magnitude = math.sqrt(x * x + y * y + z * z)
    orientation = math.degrees(math.atan2(y, x)) % 360.0
    inclination = math.degrees(math.acos(max(-1.0, min(1.0, z / magnitude)))) if magnitude else 0.0
    return magnitude, orientation, inclination


class Epuck(SerialDevice):
    """An e-puck on a serial port (Bluetooth, a cable, or the simulator's pseudo-terminal)."""

    what = "e-puck"

    def __init__(self, device: str, baud_rate: int = DEFAULT_BAUD_RATE, timeout: float = 0.5):
        super().__init__(device, baud_rate, timeout)
        self.camera: tuple[int, int, int] | None = None      # the mode, width, height asked for

    def ask(self, letter: str, *args: int) -> list[int]:
        """Send a command and return the values of its reply. A reply left over from an
        interrupted command is skipped."""
        self._discard_input()
        self._write(command_line(letter, *args))
        for attempt in range(2):
            line = self._read_line(letter)
            try:
                return parse_reply(letter, line)
            except ValueError as error:
                stale = line[:1].isalpha() and line[:1].islower() and attempt == 0
                if not stale:
                    self._discard_input()
                    raise DeviceError(f"the e-puck at '{self.device}' gave a corrupted reply "
                                      f"to command {letter}: {error}") from None
        raise AssertionError("unreachable")

    def _read_line(self, letter: str) -> bytes:
        try:
            line = self.port.read_until(b"\n", 256)
        except Exception as error:
            raise DeviceError(f"the e-puck at '{self.device}' cannot be read: {error}") from None
        if not line.endswith(b"\n"):
            raise NotAnswering(f"the e-puck at '{self.device}' does not answer (command "
                               f"{letter}, no reply within {self.timeout} s)")
        return line

    def _discard_input(self) -> None:
        try:
            self.port.reset_input_buffer()
        except Exception as error:
            raise DeviceError(f"the e-puck at '{self.device}' cannot be read: {error}") from None

    def _values(self, letter: str, count: int) -> list[int]:
        values = self.ask(letter)
        if len(values) != count:
            raise DeviceError(f"the e-puck at '{self.device}' gave a corrupted reply to "
                              f"command {letter}: {len(values)} values instead of {count}")
        return values

    def set_speed(self, left: int, right: int) -> None:
        """Wheel speeds in steps/s, clipped to ±1000."""
        limit = MAX_STEPS_PER_SECOND
        self.ask("D", max(-limit, min(limit, left)), max(-limit, min(limit, right)))

    def proximity(self) -> list[int]:
        return self._values("N", 8)

    def encoders(self) -> list[int]:
        return self._values("Q", 2)

    def accelerometer(self) -> list[int]:
        return self._values("A", 3)

    def microphones(self) -> list[int]:
        return self._values("U", 3)

    def set_led(self, number: int, on: bool) -> None:
        self.ask("L", number, 1 if on else 0)

    def set_body_led(self, on: bool) -> None:
        self.ask("B", 1 if on else 0)

    def set_front_led(self, on: bool) -> None:
        self.ask("F", 1 if on else 0)

    def play_sound(self, number: int) -> None:
        self.ask("T", number)

    def calibrate(self, seconds: float = CALIBRATION_SECONDS) -> None:
        """Calibrate the proximity sensors. The firmware answers ``k, Starting calibration -
        Remove any object in sensors range`` at once and ``k, Calibration finished`` when it
        is done (waited for up to ``seconds``)."""
        self._discard_input()
        self._write(command_line("K"))
        normal = self.port.timeout
        try:
            for step, waited in (("start", normal), ("end", seconds)):
                self.port.timeout, self.timeout = waited, waited
                text = self._read_line("K").decode("ascii", "replace").strip()
                if not text.startswith("k,"):
                    self._discard_input()
                    raise DeviceError(f"the e-puck at '{self.device}' gave a corrupted reply to "
                                      f"command K (calibration {step}): '{text[:60]}'")
        finally:
            self.port.timeout, self.timeout = normal, normal

    def set_camera(self, colour: bool, width: int, height: int, zoom: int) -> None:
        """Ask for ``width`` x ``height`` images; one that does not fit the robot's buffer is
        refused here (the firmware would send another format)."""
        if not image_fits(colour, width, height):
            raise DeviceError(f"a {width} x {height} {'colour' if colour else 'grey'} image "
                              f"({image_bytes(colour, width, height)} bytes) does not fit the "
                              f"e-puck's camera buffer: {IMAGE_PIXEL_BYTES} bytes at most")
        self.ask("J", 1 if colour else 0, width, height, zoom)
        self.camera = (1 if colour else 0, width, height)

    def image(self) -> np.ndarray:
        """One camera image in 0..1 (see :func:`decode_image`), of the format asked for with
        :meth:`set_camera` (another format is an error naming the robot)."""
        self.port.reset_input_buffer()
        self._write(IMAGE_COMMAND)
        header = self._read(IMAGE_HEADER, "camera image header")
        mode, width, height = header
        if mode not in (0, 1) or not width or not height:
            raise DeviceError(f"the e-puck at '{self.device}' gave a corrupted camera header "
                              f"{list(header)}")
        data = self._read(width * height * (1 + mode), "camera image")
        if self.camera is not None and (mode, width, height) != self.camera:
            asked = self.camera
            raise DeviceError(f"the e-puck at '{self.device}' sent a {width} x {height} "
                              f"{_MODES[mode]} image, not the {asked[1]} x {asked[2]} "
                              f"{_MODES[asked[0]]} one asked for (images of more than "
                              f"{IMAGE_PIXEL_BYTES} bytes do not fit its buffer)")
        return decode_image(data, mode, width, height)

    def safe_state(self) -> None:
        """Wheels stopped, every LED off, no sound. Every step is tried even when one gets a
        wrong reply (the first failure is raised at the end); a robot that does not answer
        at all ends it at once."""
        steps = [("S",)] + [("L", n, 0) for n in range(RING_LEDS)] + [("B", 0), ("F", 0),
                                                                    ("T", 0)]
        failure = None
        for step in steps:
            try:
                self.ask(*step)
            except NotAnswering:
                raise
            except DeviceError as error:
                failure = failure or error
        if failure is not None:
            raise failure
