"""The e-puck protocol at the byte level, the virtual e-puck and its arena, and the driver."""
from __future__ import annotations

import math
import time

import numpy as np
import pytest

from ikaros.hardware import DeviceError
from ikaros.hardware.epuck import (AXLE_LENGTH, IMAGE_BUFFER, IMAGE_COMMAND, IMAGE_PIXEL_BYTES,
                                   METRES_PER_STEP,
                                   ROBOT_RADIUS, Epuck,
                                   acceleration_figures, command_line, decode_image,
                                   encode_image, parse_reply)
from ikaros.hardware.epuck_sim import Arena, VirtualEpuck, parse_boxes
from ikaros.hardware.serial_port import open_serial


def test_command_and_reply_bytes():
    assert command_line("D", 500, -500) == b"D,500,-500\r"
    assert command_line("N") == b"N\r"
    assert command_line("L", 3, 1) == b"L,3,1\r"
    assert parse_reply("N", b"n,1,2,3,4,5,6,7,8\r\n") == [1, 2, 3, 4, 5, 6, 7, 8]
    assert parse_reply("D", b"d\r\n") == []
    with pytest.raises(ValueError, match="not a reply to Q"):
        parse_reply("Q", b"n,1,2\r\n")
    with pytest.raises(ValueError, match="not a whole number"):
        parse_reply("Q", b"q,1,x\r\n")


def test_image_encoding_round_trip():
    grey = np.array([[0.0, 1.0], [0.5, 0.2]])
    assert encode_image(grey) == bytes([0, 255, 128, 51])
    colour = np.zeros((1, 2, 3))
    colour[0, 0] = (1, 0, 0)
    colour[0, 1] = (0, 1, 1)
    assert encode_image(colour) == bytes([0xF8, 0x00, 0x07, 0xFF])      # RGB565, big-endian
    assert np.allclose(decode_image(encode_image(colour), 1, 2, 1), colour)
    assert np.allclose(decode_image(bytes([0, 255, 128, 51]), 0, 2, 2),
                       [[0, 1], [128 / 255, 51 / 255]])


def test_acceleration_figures():
    assert acceleration_figures((2048, 2048, 2848)) == (1.0, 0.0, 0.0)  # flat, 1 g
    g, orientation, inclination = acceleration_figures((2048, 2848, 2048))  # on its side
    assert (g, orientation, inclination) == pytest.approx((1.0, 90.0, 90.0))


def test_arena_rays_and_clearance():
    assert parse_boxes("none") == []
    assert parse_boxes("1,2,3,4;5,6,7,8") == [(1, 2, 3, 4), (5, 6, 7, 8)]
    arena = Arena(1.0, 0.5, parse_boxes("0.6,0.1,0.8,0.3"))
    assert arena.cast((0.1, 0.2), 0.0, 2.0) == pytest.approx((0.5, True))
    assert arena.cast((0.1, 0.2), math.pi, 2.0) == pytest.approx((0.1, False))
    assert arena.cast((0.1, 0.2), math.pi / 2, 2.0) == pytest.approx((0.3, False))
    assert arena.cast((0.1, 0.2), 0.0, 0.3) == (0.3, False)          # out of range
    assert arena.clearance((0.5, 0.2)) == pytest.approx(0.1)
    assert arena.clearance((0.85, 0.35)) == pytest.approx(math.hypot(0.05, 0.05))  # a corner


def test_driving_follows_differential_drive():
    robot = VirtualEpuck(Arena(2, 2, []), x=1.0, y=1.0, heading=0.0, step=0.1)
    robot.speeds = [500, 500]
    robot.advance(1.0)
    assert robot.pose == pytest.approx([1.0 + 500 * METRES_PER_STEP, 1.0, 0.0])
    robot.speeds = [-300, 300]                                        # turn on the spot
    robot.advance(0.5)
    turn = 2 * 300 * METRES_PER_STEP / AXLE_LENGTH * 0.5
    assert robot.pose[2] == pytest.approx(turn)
    assert list(robot.encoders) == [500 - 150, 500 + 150]
    assert robot.distance == pytest.approx(500 * METRES_PER_STEP)


def test_walls_stop_the_robot_and_count_contacts():
    robot = VirtualEpuck(Arena(0.5, 0.5, []), x=0.25, y=0.25, heading=0.0)
    robot.speeds = [1000, 1000]
    robot.advance(5.0)
    assert robot.pose[0] == pytest.approx(0.5 - ROBOT_RADIUS, abs=0.001)
    assert robot.contacts == 1
    robot.speeds = [-1000, -1000]
    robot.advance(0.2)
    robot.speeds = [1000, 1000]
    robot.advance(1.0)
    assert robot.contacts == 2


def test_proximity_falls_with_distance_and_calibration_removes_the_base():
    robot = VirtualEpuck(Arena(1, 1, []), x=0.5, y=1 - ROBOT_RADIUS - 0.01, heading=0.0)
    values = robot.raw_proximity()          # sensors 5 (left, 90°) faces the wall 1 cm away
    assert values[5] == pytest.approx(60 + 3700 * math.exp(-0.01 / 0.012))
    assert values[2] == pytest.approx(60, abs=0.01)                  # right: nothing near
    ray = (0.01 + ROBOT_RADIUS * (1 - math.sin(math.pi / 4))) / math.sin(math.pi / 4)
    assert values[6] == pytest.approx(60 + 3700 * math.exp(-ray / 0.012))   # 45°: 2.9 cm
    assert values[7] == values[0] == 60                              # 10°: beyond 10 cm


@pytest.fixture
def epuck():
    with VirtualEpuck(Arena(1, 1, parse_boxes("0.6,0.1,0.8,0.3")), x=0.2, y=0.2,
                      step=0.1) as robot:
        driver = Epuck(robot.path, timeout=0.3)
        yield robot, driver
        driver.close()


def test_simulator_answers_raw_bytes(epuck):
    robot, _ = epuck
    port = open_serial(robot.path, 115200, timeout=1.0, what="e-puck")
    try:
        port.write(b"D,200,200\rQ\r")
        assert port.read_until(b"\n") == b"d\r\n"
        assert port.read_until(b"\n") == b"q,0,0\r\n"
        port.write(b"D,0,0\rQ\rV\rX\r")
        assert port.read_until(b"\n") == b"d\r\n"
        assert port.read_until(b"\n") == b"q,20,20\r\n"                 # 200 steps/s, 0.1 s
        assert port.read_until(b"\n").startswith(b"v,Version")
        assert port.read_until(b"\n") == b"z\r\n"                       # unknown command
    finally:
        port.close()


def test_driver_commands_reach_the_robot_and_sensors_come_back(epuck):
    robot, driver = epuck
    driver.calibrate()
    assert driver.proximity() == [0] * 8
    driver.set_speed(1500, -200)                    # clipped to 1000
    assert robot.speeds == [1000, -200]
    driver.set_speed(0, 0)
    assert driver.encoders() == [100, -20]
    driver.set_led(2, True)
    driver.set_body_led(True)
    driver.set_front_led(True)
    driver.play_sound(3)
    assert (robot.leds[2], robot.body_led, robot.front_led, robot.sound) == (1, 1, 1, 3)
    assert acceleration_figures(driver.accelerometer()) == (1.0, 0.0, 0.0)
    assert driver.microphones() == [400, 400, 400]
    driver.safe_state()
    assert robot.speeds == [0, 0] and robot.leds == [0] * 8
    assert (robot.body_led, robot.front_led, robot.sound) == (0, 0, 0)


def test_camera_sees_the_obstacle_ahead(epuck):
    robot, driver = epuck
    driver.set_camera(True, 20, 10, 8)
    image = driver.image()
    assert image.shape == (10, 20, 3)
    middle = image[5, 10]
    assert middle[0] > 0.7 and middle[1] < 0.35          # the red obstacle straight ahead
    driver.set_camera(False, 8, 6, 8)
    assert driver.image().shape == (6, 8)


def test_calibration_is_answered_with_the_firmwares_two_lines(epuck):
    """The e-puck firmware answers K with 'k, Starting calibration - Remove any object in
    sensors range' and, when done, 'k, Calibration finished' (as the issue quotes them)."""
    robot, driver = epuck
    port = open_serial(robot.path, 115200, timeout=1.0, what="e-puck")
    try:
        port.write(b"K\r")
        assert port.read_until(b"\n") == b"k, Starting calibration - Remove any object in sensors range\r\n"
        assert port.read_until(b"\n") == b"k, Calibration finished\r\n"
    finally:
        port.close()
    driver.calibrate()
    assert driver.proximity() == [0] * 8


def test_an_image_that_does_not_fit_the_buffer(epuck):
    """GCtronic, "Advanced sercom protocol", command J: "The total image size must not exceed
    4056 bytes" (52*39*2; the e-puck2's buffer is 4056 + 3 + 80 = 4139 bytes). The firmware
    answers j to 80 x 60 grey and sends 40 x 40 RGB565. The driver refuses such a request, and
    names the robot when a header disagrees with the request."""
    robot, driver = epuck
    assert IMAGE_PIXEL_BYTES == 52 * 39 * 2 == 4056 and IMAGE_BUFFER == 4139
    port = open_serial(robot.path, 115200, timeout=1.0, what="e-puck")
    try:
        port.write(b"J,0,80,60,8\r")
        assert port.read_until(b"\n") == b"j\r\n"
        port.write(IMAGE_COMMAND)
        assert port.read(3) == bytes([1, 40, 40])
        assert len(port.read(40 * 40 * 2)) == 3200
    finally:
        port.close()
    with pytest.raises(DeviceError, match="a 64 x 64 grey image \\(4096 bytes\\) does not fit the e-puck's "
                                          "camera buffer: 4056 bytes at most"):
        driver.set_camera(False, 64, 64, 8)
    driver.set_camera(False, 63, 64, 8)                  # 4032 bytes: fits
    assert driver.image().shape == (64, 63)
    robot.camera = (1, 40, 40, 8)                        # the robot switched format on its own
    with pytest.raises(DeviceError, match=f"the e-puck at '{robot.path}' sent a 40 x 40 colour image, not "
                                          f"the 63 x 64 grey one asked for"):
        driver.image()


@pytest.mark.parametrize("fault, message", [("silent", "does not answer \\(command N"),
                                            ("corrupt", "gave a corrupted reply to command N")])
def test_faults_are_reported_with_the_port(epuck, fault, message):
    robot, driver = epuck
    robot.fault = fault
    with pytest.raises(DeviceError, match=f"e-puck at '{robot.path}' " + message):
        driver.proximity()


def test_a_robot_that_disappears_is_reported(epuck):
    robot, driver = epuck
    robot.disconnect()
    with pytest.raises(DeviceError, match="e-puck"):
        driver.proximity()


def test_a_start_inside_an_obstacle_is_refused():
    with pytest.raises(ValueError, match="inside a wall or an obstacle"):
        VirtualEpuck(Arena(1, 1, parse_boxes("0.1,0.1,0.3,0.3")), x=0.2, y=0.2)


def test_replies_left_over_from_interrupted_commands_are_skipped(epuck):
    robot, driver = epuck
    driver.port.write(b"L,0,1\r")                   # its reply "l" is never read
    assert driver.encoders() == [0, 0]
    driver.port.write(b"B,1\r")
    time.sleep(0.05)                                 # the stale reply has arrived
    assert driver.encoders() == [0, 0]
    assert (robot.leds[0], robot.body_led) == (1, 1)
