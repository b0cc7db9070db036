"""Epuck: the e-puck mobile robot over its serial (Bluetooth) link."""
import math
import threading

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Epuck(Module):
    """Drives an e-puck robot through its serial command protocol (Bluetooth serial, a cable, or
    ``port="sim:epuck"``: the simulated robot in a 2-D arena, see docs/robots.md). VELOCITY
    (left, right) sets the wheel speeds, 1 being ``velocity_scale`` steps/s (1000 steps/s, the
    top speed, is about 12.9 cm/s); LED (8 values) switches the ring LEDs, LIGHT the front LED
    and BODY the body LED (on above 0.5); SOUND plays sound 1..5 when its value changes (0
    stops). Sensors are read only when switched on: PROXIMITY (``proximity_on``: the eight IR
    sensors IR0..IR7, clockwise from front right, in the robot's counts, near 0 with nothing
    within about 7 cm and several thousand at contact; calibrated at the start when
    ``calibrate`` is on, which needs the robot away from obstacles), ENCODER (``encoder_on``:
    left and right wheel steps, 1000 a turn), the accelerometer (``acceleration_on``:
    ACCELERATION_PLAIN raw x, y, z; ACCELERATION in g; ORIENTATION and INCLINATION in degrees),
    MICROPHONE_VOLUME (``microphone_on``: the three microphones' amplitudes) and the camera
    (``camera`` grey or colour, ``width`` x ``height`` pixels at ``zoom``: IMAGE grey, RED,
    GREEN and BLUE in 0..1; the pixels must fit the robot's buffer, at most 52·39·2 = 4056
    bytes (of its 4139-byte buffer, e-puck2), or the load fails naming the limit, and an
    image of another format than asked for stops the run with an error naming the port). POSE is (x, y, heading in radians): the simulator's true pose with
    ``sim:epuck``, otherwise odometry from the encoders (starting at 0, 0, 0; needs
    ``encoder_on``). Nothing is sent before the first tick, nor from an input element that has
    not yet received a value from its source (``Module.input_ready``); when the run ends the wheels are
    stopped, every LED is switched off and the sound stops; the same happens after ``watchdog``
    seconds without a tick (the model's commands are sent again when ticks resume), at
    interpreter exit, and on the ``safe_state`` command. A robot that stops answering, or
    answers wrongly, stops the run with an error naming the port. Differences from Ikaros 2: the
    ASCII protocol is used for everything but the camera (Ikaros 2 read the sensors in the
    binary protocol); MICROPHONE_BUFFER and MICROPHONE_SCAN_ID are empty (the sampled sound
    buffer is not read); POSE, velocity_scale, baud_rate and watchdog are new."""

    port = Parameter("/dev/rfcomm", "the serial device (e.g. /dev/rfcomm0 for Bluetooth), or "
                     "sim:epuck?options for the simulator")
    baud_rate = Parameter(115200, "baud rate of a cable connection")
    calibrate = Parameter(True, "calibrate the proximity sensors at the start")
    camera = Parameter("none", "the camera image to read", options="none/gray/color")
    height = Parameter(32, "camera image height, pixels")
    width = Parameter(32, "camera image width, pixels")
    zoom = Parameter(8, "camera zoom (1, 2, 4 or 8)")
    proximity_on = Parameter(False, "read the proximity sensors every tick")
    encoder_on = Parameter(False, "read the wheel encoders every tick")
    acceleration_on = Parameter(False, "read the accelerometer every tick")
    microphone_on = Parameter(False, "read the microphone amplitudes every tick")
    velocity_scale = Parameter(1000.0, "wheel speed in steps/s for a VELOCITY of 1")
    watchdog = Parameter(1.0, "seconds without a tick before the robot is put in the safe "
                         "state (0: never)")

    VELOCITY = Input("left and right wheel speed, 1 = velocity_scale steps/s", optional=True)
    LED = Input("the eight ring LEDs, on above 0.5", optional=True)
    LIGHT = Input("the front LED, on above 0.5", optional=True)
    BODY = Input("the body LED, on above 0.5", optional=True)
    SOUND = Input("the sound to play (1..5, 0 stops) when it changes", optional=True)

    PROXIMITY = Output("the eight proximity sensors IR0..IR7, counts", size="8")
    ACCELERATION_PLAIN = Output("raw accelerometer x, y, z", size="3")
    ACCELERATION = Output("magnitude of the acceleration, g", size="1")
    ORIENTATION = Output("direction of the horizontal acceleration, degrees", size="1")
    INCLINATION = Output("angle between the robot's vertical and the acceleration, degrees",
                         size="1")
    ENCODER = Output("left and right wheel encoders, steps", size="2")
    MICROPHONE_VOLUME = Output("amplitudes of the three microphones", size="3")
    MICROPHONE_BUFFER = Output("the sampled sound (not read: empty)", optional=True)
    MICROPHONE_SCAN_ID = Output("the sound buffer's scan id (not read: empty)", optional=True)
    IMAGE = Output("the grey camera image, 0..1", size_param_x="width", size_param_y="height")
    RED = Output("red of the colour camera image, 0..1", size_param_x="width",
                 size_param_y="height")
    GREEN = Output("green of the colour camera image, 0..1", size_param_x="width",
                   size_param_y="height")
    BLUE = Output("blue of the colour camera image, 0..1", size_param_x="width",
                  size_param_y="height")
    POSE = Output("x, y (metres) and heading (radians): the simulator's pose, or odometry",
                  size="3")

    def init(self):
        from ikaros.hardware import safety
        from ikaros.hardware.epuck import IMAGE_PIXEL_BYTES, image_bytes, image_fits
        from ikaros.hardware.epuck import Epuck as Robot
        from ikaros.hardware.simulators import open_device_string
        self._simulator = self._robot = self._watchdog = self._exit_key = None
        self._lock = threading.Lock()
        colour = self.camera == "color"
        if self.camera != "none" and not image_fits(colour, int(self.width), int(self.height)):
            raise ValueError(f"a {self.width} x {self.height} {self.camera} image "
                             f"({image_bytes(colour, int(self.width), int(self.height))} bytes) "
                             f"does not fit the e-puck's camera buffer: {IMAGE_PIXEL_BYTES} bytes "
                             f"at most (grey 1 byte a pixel, colour 2)")
        self._sent = {}
        self._last_encoders = None
        try:
            device, self._simulator = open_device_string(self.port)
            self._robot = Robot(device, int(self.baud_rate))
            if self.calibrate and self.proximity_on:
                self._robot.calibrate()
            if self.encoder_on:
                self.ENCODER[...] = self._robot.encoders()
            if self.camera != "none":
                self._robot.set_camera(self.camera == "color", int(self.width),
                                       int(self.height), int(self.zoom))
        except Exception:
            self.stop()
            raise
        self._exit_key = safety.on_exit(f"the e-puck at {device}", self._safe_state)
        self._watchdog = safety.Watchdog(float(self.watchdog), self._safe_state,
                                         f"{self.path}-watchdog")
        self._write_pose()

    def _changed(self, key, value) -> bool:
        """True (and remembered) when ``value`` differs from what was last sent for ``key``."""
        if self._sent.get(key) == value:
            return False
        self._sent[key] = value
        return True

    def _on(self, value, index=0) -> bool:
        return bool(value.reshape(-1)[index] > 0.5)

    def tick(self):
        with self._lock:
            if self._watchdog.kick():            # made safe while idle: send everything again
                self._sent.clear()
            self._tick()

    def _given(self, name: str, count: int = 1) -> bool:
        """Whether input ``name`` is connected and its first ``count`` elements hold values
        from their source (before that nothing is sent: nothing moves at start-up)."""
        return getattr(self, name) is not None and bool(self.input_ready(name)[:count].all())

    def _tick(self):
        robot = self._robot
        if self._given("VELOCITY", 2):
            left, right = (float(v) * self.velocity_scale for v in self.VELOCITY.reshape(-1)[:2])
            robot.set_speed(int(round(left)), int(round(right)))
        if self.LED is not None:
            ready = self.input_ready("LED")
            for n in range(min(8, self.LED.size)):
                if ready[n] and self._changed(("led", n), self._on(self.LED, n)):
                    robot.set_led(n, self._sent[("led", n)])
        if self._given("LIGHT") and self._changed("light", self._on(self.LIGHT)):
            robot.set_front_led(self._sent["light"])
        if self._given("BODY") and self._changed("body", self._on(self.BODY)):
            robot.set_body_led(self._sent["body"])
        if self._given("SOUND") and self._changed("sound", int(round(float(self.SOUND.flat[0])))):
            robot.play_sound(self._sent["sound"])
        self._read_sensors(robot)
        self._write_pose()

    def _read_sensors(self, robot):
        from ikaros.hardware.epuck import acceleration_figures
        if self.proximity_on:
            self.PROXIMITY[...] = robot.proximity()
        if self.encoder_on:
            self.ENCODER[...] = robot.encoders()
        if self.acceleration_on:
            raw = robot.accelerometer()
            self.ACCELERATION_PLAIN[...] = raw
            (self.ACCELERATION[0], self.ORIENTATION[0],
             self.INCLINATION[0]) = acceleration_figures(raw)
        if self.microphone_on:
            self.MICROPHONE_VOLUME[...] = robot.microphones()
        if self.camera == "gray":
            self.IMAGE[...] = robot.image()
        elif self.camera == "color":
            image = robot.image()
            self.RED[...], self.GREEN[...], self.BLUE[...] = (image[..., k] for k in range(3))
            self.IMAGE[...] = image.mean(axis=2)

    def _write_pose(self):
        from ikaros.hardware.epuck import AXLE_LENGTH, METRES_PER_STEP
        if self._simulator is not None:
            with self._simulator.lock:
                self.POSE[...] = self._simulator.pose
            return
        if not self.encoder_on:
            return
        steps = np.asarray(self.ENCODER, np.float64)
        if self._last_encoders is not None:
            left, right = (steps - self._last_encoders) * METRES_PER_STEP
            x, y, heading = (float(v) for v in self.POSE)
            forward, turn = (left + right) / 2, (right - left) / AXLE_LENGTH
            self.POSE[0] = x + forward * math.cos(heading + turn / 2)
            self.POSE[1] = y + forward * math.sin(heading + turn / 2)
            self.POSE[2] = (heading + turn + math.pi) % (2 * math.pi) - math.pi
        self._last_encoders = steps

    def command(self, name, x=0, y=0, value=None):
        if name == "safe_state":
            self._safe_state()

    def _safe_state(self):
        """Wheels stopped, LEDs off, no sound (called by stop, the watchdog and at exit)."""
        with self._lock:
            if self._robot is not None:
                self._robot.safe_state()
                self._sent.clear()

    def stop(self):
        from ikaros.hardware import safety
        safety.shut_down(self._watchdog, self._safe_state, self._exit_key, self._robot,
                         self._simulator, lambda error: self.error(
                             f"the e-puck could not be put in the safe state: {error}"))
        self._robot = self._simulator = None
