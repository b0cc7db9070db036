"""A stand-in robot for examples/ros2/braitenberg.ikg: a round robot in a 4 m square room
that speaks ROS 2 as a real mobile base does. It publishes two range readings (left and
right, 30 degrees off its heading, up to 2 m) on /ranges as std_msgs/Float32MultiArray and
its pose (x, y, heading) on /pose, and drives by the geometry_msgs/Twist it reads on
/cmd_vel, 50 times a second.

    python examples/ros2/standin_robot.py --loopback --seconds 60

--loopback keeps DDS on this machine (no other ROS 2 node then sees it)."""
import argparse
import math
import os
import time

import numpy as np

from ikaros.hardware.ros2 import LOOPBACK
from ikaros.hardware.ros2.messages import layout_of, message_type

HALF_ROOM, MAX_RANGE, SENSOR_ANGLE, RATE = 2.0, 2.0, math.radians(30), 50.0


def distance_to_wall(x: float, y: float, angle: float) -> float:
    """How far a ray from (x, y) in direction ``angle`` runs before it meets a wall."""
    dx, dy = math.cos(angle), math.sin(angle)
    hits = [(HALF_ROOM * math.copysign(1, d) - p) / d for p, d in ((x, dx), (y, dy))
            if abs(d) > 1e-9]
    return min(MAX_RANGE, min(h for h in hits if h >= 0))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=float("inf"))
    parser.add_argument("--loopback", action="store_true")
    options = parser.parse_args()
    if options.loopback:
        os.environ["CYCLONEDDS_URI"] = LOOPBACK
    from ikaros.hardware.ros2 import dds       # after CYCLONEDDS_URI is set
    array, twist = message_type("std_msgs/Float32MultiArray"), message_type("geometry_msgs/Twist")
    domain = dds.domain_id()
    ranges = dds.Publisher("/ranges", array, "sensor_data", domain)
    pose_out = dds.Publisher("/pose", array, "sensor_data", domain)
    commands = dds.Subscription("/cmd_vel", twist, "default", domain)
    x, y, heading = 0.0, 0.0, 0.4       # not square to the walls: it has to turn
    end = time.monotonic() + options.seconds
    print("stand-in robot: /ranges and /pose out, /cmd_vel in", flush=True)
    while time.monotonic() < end:
        latest = commands.latest()
        speed, turn = 0.0, 0.0
        if latest is not None and time.monotonic() - latest[1] < 0.5:   # a stale command: stop
            command = twist.decode(latest[0])
            speed, turn = command["linear"][0], command["angular"][2]
        heading += turn / RATE
        x = float(np.clip(x + speed * math.cos(heading) / RATE, -HALF_ROOM + 0.1, HALF_ROOM - 0.1))
        y = float(np.clip(y + speed * math.sin(heading) / RATE, -HALF_ROOM + 0.1, HALF_ROOM - 0.1))
        readings = [distance_to_wall(x, y, heading + SENSOR_ANGLE),
                    distance_to_wall(x, y, heading - SENSOR_ANGLE)]
        ranges.publish(array.encode({"layout": layout_of((2,)), "data": readings}))
        pose_out.publish(array.encode({"layout": layout_of((3,)), "data": [x, y, heading]}))
        time.sleep(1.0 / RATE)


if __name__ == "__main__":
    main()
