"""ROS 2 figures: DDS round trips, the cost of publishing, MCAP recording against HDF5.

    python benchmarks/ros2.py             # about a minute

Printed:
* round trip model -> DDS -> echo node -> DDS -> model on this machine (loopback, Cyclone
  DDS), for a 16-value Float32MultiArray and a 640x480 rgb8 Image: median and p99 over
  ``--trips`` messages; the echo node is a separate process that sends back the bytes it gets;
* the cost per tick of ROS2Publisher (16 values; a 640x480 colour image) and of
  ROS2Subscriber (16 values), from the module's profiled time;
* recording cost per tick: robot_320 (benchmarks/models.py, 320 modules) run 2000 ticks in
  batch mode without a recording, with HDF5 and with MCAP.
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from ikaros.hardware.ros2 import LOOPBACK  # noqa: E402

os.environ["CYCLONEDDS_URI"] = LOOPBACK
DOMAIN = str(150 + os.getpid() % 50)
os.environ["ROS_DOMAIN_ID"] = DOMAIN

import numpy as np  # noqa: E402

import ikaros  # noqa: E402
from benchmarks import models  # noqa: E402
from ikaros.hardware.ros2 import dds  # noqa: E402
from ikaros.hardware.ros2.messages import layout_of, message_type  # noqa: E402

ECHO = """
import sys, time
from ikaros.hardware.ros2 import dds
from ikaros.hardware.ros2.messages import message_type
kind = message_type(sys.argv[1])
back = dds.Publisher("/bench_pong", kind, "default", dds.domain_id())
sub = dds.Subscription("/bench_ping", kind, "default", dds.domain_id())
print("READY", flush=True)
seen = None
end = time.monotonic() + 120
while time.monotonic() < end:
    latest = sub.latest()
    if latest is not None and latest[1] != seen:
        seen = latest[1]
        back.publish(bytes(latest[0]))
    time.sleep(0.0002)
"""


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


def round_trips(kind_name: str, message: dict, trips: int) -> list[float]:
    env = dict(os.environ, PYTHONPATH=ROOT)
    echo = subprocess.Popen([sys.executable, "-c", ECHO, kind_name], stdout=subprocess.PIPE,
                            text=True, env=env)
    try:
        assert echo.stdout.readline().strip() == "READY"
        kind = message_type(kind_name)
        ping = dds.Publisher("/bench_ping", kind, "default", dds.domain_id())
        pong = dds.Subscription("/bench_pong", kind, "default", dds.domain_id())
        data = kind.encode(message)
        times, seen = [], None
        deadline = time.monotonic() + 10          # until the echo node is matched
        while pong.latest() is None and time.monotonic() < deadline:
            ping.publish(data)
            time.sleep(0.05)
        seen = pong.latest()[1] if pong.latest() else None
        for _ in range(trips):
            started = time.monotonic()
            ping.publish(data)
            while True:
                latest = pong.latest()
                if latest is not None and latest[1] != seen:
                    seen = latest[1]
                    times.append(latest[1] - started)
                    break
                if time.monotonic() - started > 2:
                    break
        return times
    finally:
        echo.kill()
        echo.wait()


def module_cost(folder: str, text: str, module: str, ticks: int = 500) -> float:
    path = os.path.join(folder, "cost.ikg")
    with open(path, "w") as f:
        f.write(text)
    with ikaros.load(path) as net:
        net.profiling = True
        net.run(ticks=ticks)
        return next(m["mean"] for m in net.module_figures() if m["module"].endswith(module))


def recording_cost(folder: str, ticks: int) -> dict:
    path = models.robot_320(folder)
    out = {}
    for kind in ("none", "h5", "mcap"):
        with ikaros.load(path) as net:
            recording = None if kind == "none" else net.record(os.path.join(folder, f"r.{kind}"))
            started = time.perf_counter()
            net.run(ticks=ticks)
            if recording is not None:
                recording.close()
            out[kind] = (time.perf_counter() - started) / ticks
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--trips", type=int, default=300)
    options = parser.parse_args()
    ms = 1000.0
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    small = {"layout": layout_of((16,)), "data": np.arange(16, dtype=np.float32)}
    image = {"header": {"stamp": (0, 0), "frame_id": "camera"}, "height": 480, "width": 640,
             "encoding": "rgb8", "is_bigendian": 0, "step": 640 * 3,
             "data": bytes(640 * 480 * 3)}
    for name, kind, message, trips in (
            ("16 values", "std_msgs/msg/Float32MultiArray", small, options.trips),
            ("640x480 rgb8 image", "sensor_msgs/msg/Image", image, options.trips // 3)):
        times = round_trips(kind, message, trips)
        print(f"round trip, {name}: median {statistics.median(times) * ms:.3f} ms, "
              f"p99 {percentile(times, 0.99) * ms:.3f} ms ({len(times)} of {trips})")
    with tempfile.TemporaryDirectory() as folder:
        publish16 = module_cost(folder, """<group><module class="Constant" name="C"
            data="1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16"/><module class="ROS2Publisher"
            name="P" topic="/bench_cost"/><connection source="C.OUTPUT" target="P.INPUT"/>
            </group>""", "P")
        publish_image = module_cost(folder, """<group><module class="SyntheticCamera"
            name="C" size_x="640" size_y="480"/><module class="ROS2Publisher" name="P"
            topic="/bench_image" type="Image"/><connection source="C.OUTPUT" target="P.INPUT"/>
            </group>""", "P", ticks=100)
        subscribe16 = module_cost(folder, """<group><module class="ROS2Subscriber" name="S"
            topic="/bench_cost" size="16"/></group>""", "S")
        print(f"ROS2Publisher per tick: 16 values {publish16 * ms:.3f} ms, 640x480 colour "
              f"image {publish_image * ms:.2f} ms; ROS2Subscriber (16 values, no message) "
              f"{subscribe16 * ms:.3f} ms")
        cost = recording_cost(folder, 2000)
        print(f"robot_320, 2000 ticks: {cost['none'] * ms:.3f} ms a tick without recording, "
              f"{cost['h5'] * ms:.3f} ms with HDF5, {cost['mcap'] * ms:.3f} ms with MCAP "
              f"(the MCAP writer thread encodes 320 messages a tick)")


if __name__ == "__main__":
    main()
