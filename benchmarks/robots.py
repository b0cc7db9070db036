"""Hardware in the loop: the Epi humanoid's Dynamixel bus against the simulator.

    python benchmarks/robots.py            # about 15 s
    python benchmarks/robots.py --ticks 1000

The simulator (`ikaros-sim dynamixel --ids 1-19 --protocol 2 --line-time`) runs in its own
process, as a real bus would, and makes every packet take its wire time at the port's baud
rate (1 Mbaud, 10 bits a byte) plus each servo's Return Delay Time (set to 0, as on the Epi;
the factory 250 = 500 µs per answer is printed for comparison).

Printed:
* bus round trip per tick: one sync write of 19 goal positions and one sync read of 19
  present positions, through dynamixel-sdk (median and 99th percentile), and the wire time
  of those bytes alone;
* servos per tick: the round trip measured for 1, 5, 10 and 19 servos, fitted by a line
  a + b·n, and the most servos whose round trip fits a 10 ms (100 Hz) and a 20 ms (50 Hz,
  the Bioloid's rate) tick;
* the Dynamixel module at 100 Hz in real time with those 19 servos (GOAL_POSITION from a
  sine per servo, feedback=position): tick lag p99 and the module's mean and max time.
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

from ikaros.hardware.dynamixel.bus import DynamixelBus  # noqa: E402

SERVOS = 19
LATENCY_MS = 30.0       # a generous wait for answers: the simulator shares a loaded machine
BAUD = 1000000
GOAL, PRESENT, SIZE = 116, 132, 4        # X-series addresses of Goal and Present Position


def start_simulator() -> tuple[subprocess.Popen, str]:
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    process = subprocess.Popen([sys.executable, "-m", "ikaros.hardware.sim_cli", "dynamixel", "--ids",
                                f"1-{SERVOS}", "--protocol", "2", "--line-time"],
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env)
    return process, process.stdout.readline().strip()


def round_trips(bus: DynamixelBus, ids: list[int], count: int) -> list[float]:
    times = []
    goal = (2048).to_bytes(SIZE, "little")
    for _ in range(count):
        started = time.perf_counter()
        bus.sync_write(GOAL, SIZE, {i: goal for i in ids})
        bus.sync_read(PRESENT, SIZE, ids)
        times.append(time.perf_counter() - started)
    return times


def wire_seconds(n: int) -> float:
    sync_write = 14 + (1 + SIZE) * n        # header 7, instruction 1, address 2, length 2, CRC 2
    sync_read = 14 + n
    status = (11 + SIZE) * n
    return (sync_write + sync_read + status) * 10 / BAUD


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


def module_run(path: str, ticks: int) -> dict:
    from ikaros import load
    goals = " ".join(f"{180 + 20 * ((i % 3) - 1)}" for i in range(SERVOS))
    model = (f'<group name="EpiBus" tick_duration="0.01">\n'
             f'<module class="Constant" name="Goals" data="{goals}"/>\n'
             f'<module class="Dynamixel" name="Servos" device="{path}" servo_id="{" ".join(map(str, range(1, SERVOS + 1)))}" '
             f'index_mode="indirect" protocol="2" feedback="position" max_temperature="0" print_info="none" '
             f'serial_latency="{LATENCY_MS}"/>\n'
             f'<module class="Constant" name="Torque" data="{" ".join("1" for _ in range(SERVOS))}"/>\n'
             '<connection source="Goals.OUTPUT" target="Servos.GOAL_POSITION"/>\n'
             '<connection source="Torque.OUTPUT" target="Servos.TORQUE_LIMIT"/>\n</group>\n')
    with tempfile.TemporaryDirectory() as folder:
        file = os.path.join(folder, "epibus.ikg")
        with open(file, "w") as f:
            f.write(model)
        net = load(file)
        try:
            net.profiling = True
            net.run(ticks=ticks, real_time=True)
            figures = net.figures()
            module = next(m for m in net.module_figures() if m["module"].endswith("Servos"))
        finally:
            net.close()
    return {"lag_p99": figures["lag_p99"], "lag_max": figures["lag_max"], "mean": module["mean"],
            "max": module["max"], "ticks_per_second": figures["ticks_per_second"]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ticks", type=int, default=500, help="ticks of the module run (default 500 = 5 s)")
    parser.add_argument("--repeats", type=int, default=200, help="round trips per measurement (default 200)")
    options = parser.parse_args()
    process, path = start_simulator()
    ms = 1000.0
    try:
        bus = DynamixelBus(path, BAUD, 2, LATENCY_MS)
        ids = list(range(1, SERVOS + 1))
        for ident in ids:                         # the Epi's servos answer without delay
            bus.write(ident, 9, b"\x00")
        trips = round_trips(bus, ids, options.repeats)
        print(f"Epi bus: {SERVOS} servos, Protocol 2.0, {BAUD} baud, simulator with wire time")
        print(f"  round trip per tick (sync write + sync read of positions): median "
              f"{statistics.median(trips) * ms:.2f} ms, p99 {percentile(trips, 0.99) * ms:.2f} ms; "
              f"wire time alone {wire_seconds(SERVOS) * ms:.2f} ms")
        fit_n, fit_t = [], []
        for n in (1, 5, 10, SERVOS):
            median = statistics.median(round_trips(bus, ids[:n], options.repeats // 2))
            fit_n.append(n)
            fit_t.append(median)
            print(f"  {n:2d} servos: median round trip {median * ms:.2f} ms")
        slope, intercept = statistics.linear_regression(fit_n, fit_t)
        print(f"  fit: {intercept * ms:.3f} ms + {slope * ms:.3f} ms per servo")
        for tick in (0.010, 0.020):
            fits = int((tick - intercept) // slope)
            print(f"  servos whose round trip fits a {tick * ms:.0f} ms tick: {fits} "
                  f"(wire time alone: {int((tick * BAUD / 10 - 28) // (2 * SIZE + 13))})")
        for ident in ids:
            bus.write(ident, 9, bytes([250]))
        slow = statistics.median(round_trips(bus, ids, options.repeats // 4))
        print(f"  with the factory Return Delay Time (250 = 500 us): median round trip {slow * ms:.2f} ms")
        for ident in ids:
            bus.write(ident, 9, b"\x00")
        bus.close()
        result = module_run(path, options.ticks)
        print(f"Dynamixel module, {SERVOS} servos at 100 Hz real time, {options.ticks} ticks: "
              f"tick lag p99 {result['lag_p99'] * ms:.2f} ms (max {result['lag_max'] * ms:.2f} ms), "
              f"module time mean {result['mean'] * ms:.2f} ms, max {result['max'] * ms:.2f} ms, "
              f"{result['ticks_per_second']:.1f} ticks/s")
    finally:
        process.terminate()
        process.wait(timeout=10)


if __name__ == "__main__":
    main()
