"""Real time on a busy machine: tick lag with and without a CPU hog, with and without the
priority request (``priority="fifo"``: SCHED_FIFO for the tick thread, memory locked).

    python benchmarks/realtime_under_load.py                 # 30 s per run, 8 runs: ~4.5 min
    python benchmarks/realtime_under_load.py --seconds 5     # a quick look

Three models, each run in a process of its own:
* robot_320 (benchmarks/models.py: 320 modules) at 1 kHz;
* the Epi bus at 100 Hz: the Dynamixel module with 19 servos (Protocol 2.0, sync write of goal
  positions and sync read of present positions every tick) against the simulator
  (``ikaros-sim dynamixel --line-time``) in a process of its own, as a real bus would be.

* 1,000 Izhikevich neurons (benchmarks/populations.py's dense network) at 1 kHz, ten 5 s runs
  beside one busy loop (issue 30's target: no resynchronisation in any run).

The hog is one busy-loop process per core (one for the spiking runs), at normal priority. Printed per run: lag p50, p99
and max over every tick (ms), resynchronisations, ticks run of those asked for (and for the
Epi bus the status packets that did not come: MISSED_REPLIES), what the
priority request was granted, and the garbage collections of each generation during the run
(count / longest, ms). SCHED_FIFO is granted only where the process may (root, or
CAP_SYS_NICE, or ``ulimit -r``); otherwise the run says what was refused and falls back to
the best nice it can get.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from benchmarks import models  # noqa: E402
from benchmarks.populations import make_case, model_text  # noqa: E402
from benchmarks.robots import BAUD, LATENCY_MS, SERVOS, start_simulator  # noqa: E402
from ikaros.hardware.dynamixel.bus import DynamixelBus  # noqa: E402

RETURN_DELAY_TIME = 9       # X-series control table address

# The run, in a child process: every tick's lag is kept by a tick hook.
RUN = """
import gc, json, sys, time
import numpy as np
import ikaros
path, ticks, settings = sys.argv[1], int(sys.argv[2]), json.loads(sys.argv[3])
net = ikaros.load(path, **settings)
collections, started = {0: [], 1: [], 2: []}, {}
def timed(phase, info):
    if phase == "start":
        started["at"] = time.perf_counter()
    else:
        collections[info["generation"]].append(time.perf_counter() - started["at"])
gc.callbacks.append(timed)
lags, done = np.zeros(ticks), [0]
def keep():
    if done[0] < ticks:
        lags[done[0]] = net.clock.lag
        done[0] += 1
net.controller.tick_hooks.append(keep)
error = None
try:
    net.run(ticks=ticks, real_time=True)
except Exception as e:
    error = f"{type(e).__name__}: {e}"
figures = net.figures()
missed = float(net.output("Servos.MISSED_REPLIES").sum()) if "Servos" in net.modules else None
net.close()
kept = lags[:done[0]]
print("RESULT", json.dumps({
    "ticks": done[0], "error": error, "resyncs": figures["resyncs"],
    "p50": float(np.percentile(kept, 50)) if done[0] else None,
    "p99": float(np.percentile(kept, 99)) if done[0] else None,
    "max": float(kept.max()) if done[0] else None,
    "priority": figures["priority"], "missed": missed,
    "gc": {g: [len(d), max(d, default=0.0)] for g, d in collections.items()}}))
"""


def epi_bus_model(folder: str, device: str) -> str:
    goals = " ".join(f"{180 + 20 * ((i % 3) - 1)}" for i in range(SERVOS))
    ids = " ".join(map(str, range(1, SERVOS + 1)))
    path = os.path.join(folder, "epi_bus.ikg")
    with open(path, "w") as f:
        f.write(f'<group name="EpiBus" tick_duration="0.01">\n'
                f'<module class="Constant" name="Goals" data="{goals}"/>\n'
                f'<module class="Dynamixel" name="Servos" device="{device}" servo_id="{ids}" index_mode="indirect" '
                f'protocol="2" feedback="position" max_temperature="0" print_info="none" '
                f'serial_latency="{LATENCY_MS}"/>\n'
                f'<module class="Constant" name="Torque" data="{" ".join("1" for _ in range(SERVOS))}"/>\n'
                f'<connection source="Goals.OUTPUT" target="Servos.GOAL_POSITION"/>\n'
                f'<connection source="Torque.OUTPUT" target="Servos.TORQUE_LIMIT"/>\n'
                f'</group>\n')
    return path


def _above_the_hog(pid: int) -> None:
    try:
        for tid in map(int, os.listdir(f"/proc/{pid}/task")):
            os.sched_setscheduler(tid, os.SCHED_FIFO, os.sched_param(45))
        print("the servo simulator runs at SCHED_FIFO 45 (servos do not share the CPU)")
    except PermissionError:
        print("the servo simulator runs at normal priority (SCHED_FIFO not permitted): under "
              "the hog it answers late, as no real servo would")


def start_hog(processes: int | None = None) -> list[subprocess.Popen]:
    """Busy-loop processes at normal priority: one a core unless told how many."""
    return [subprocess.Popen([sys.executable, "-c", "while True: pass"])
            for _ in range(processes or os.cpu_count() or 1)]


def spiking_model(folder: str) -> str:
    """The 1,000-neuron Izhikevich network of benchmarks/populations.py (dense)."""
    case = os.path.join(folder, "spiking")
    os.makedirs(case)
    make_case(case, 1000, 1.0)
    path = os.path.join(case, "spiking.ikg")
    with open(path, "w") as f:
        f.write(model_text(case, 1000))
    return path


def run(path: str, ticks: int, settings: dict) -> dict:
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    done = subprocess.run([sys.executable, "-c", RUN, path, str(ticks), json.dumps(settings)],
                          capture_output=True, text=True, env=env, timeout=ticks + 600)
    lines = [x for x in done.stdout.splitlines() if x.startswith("RESULT ")]
    if not lines:
        return {"ticks": 0, "error": done.stderr.strip().splitlines()[-1:], "resyncs": 0,
                "p50": None, "p99": None, "max": None, "priority": None, "gc": {}}
    return json.loads(lines[-1][len("RESULT "):])


def show(name: str, hog: bool, asked: bool, ticks: int, r: dict) -> None:
    ms = lambda s: "-" if s is None else f"{s * 1000:.3f}"     # noqa: E731
    granted = (r["priority"] or {}).get("tick_thread") or "normal"
    print(f"{name:10s} {'hog' if hog else 'quiet':5s} {granted:15s} "
          f"p50 {ms(r['p50']):>7s}  p99 {ms(r['p99']):>7s}  max {ms(r['max']):>8s} ms  "
          f"resyncs {r['resyncs']:3d}  ticks {r['ticks']}/{ticks}"
          + "  gc " + " ".join(f"g{g}:{n}/{ms(t)}" for g, (n, t) in r["gc"].items())
          + ("" if r.get("missed") is None else f"  missed replies {r['missed']:g}")
          + (f"  error: {r['error']}" if r["error"] else ""), flush=True)
    for refusal in (r["priority"] or {}).get("refused", []) if asked else []:
        print(f"{'':17s}refused: {refusal}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=30.0, help="per run (default 30)")
    parser.add_argument("--priority", default="fifo", help="the request (default fifo)")
    parser.add_argument("--spiking-runs", type=int, default=10,
                        help="runs of 1,000 spiking neurons at 1 kHz beside one busy loop "
                             "(default 10)")
    parser.add_argument("--spiking-seconds", type=float, default=5.0)
    options = parser.parse_args()
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}, "
          f"{'root' if os.geteuid() == 0 else 'not root'}; {options.seconds:g} s per run")
    simulator, device = start_simulator()
    try:
        # Servos are hardware of their own: they do not wait for the hog. Where the process
        # may, the simulator that stands in for them runs above it.
        _above_the_hog(simulator.pid)
        # The Epi's servos answer without delay (Return Delay Time 0); the factory's 250
        # (500 us a servo) alone makes a sync read of 19 servos take 10 ms
        bus = DynamixelBus(device, BAUD, 2, LATENCY_MS)
        for ident in range(1, SERVOS + 1):
            bus.write(ident, RETURN_DELAY_TIME, b"\x00")
        bus.close()
        with tempfile.TemporaryDirectory() as folder:
            cases = [("robot_320", models.robot_320(folder), 0.001),
                     ("epi_bus", epi_bus_model(folder, device), 0.01)]
            for name, path, dt in cases:
                ticks = int(options.seconds / dt)
                for hog in (False, True):
                    for asked in (False, True):
                        settings = {"tick_duration": dt}
                        if asked:
                            settings["priority"] = options.priority
                        hogs = start_hog() if hog else []
                        try:
                            result = run(path, ticks, settings)
                        finally:
                            for p in hogs:
                                p.kill()
                                p.wait()
                        show(name, hog, asked, ticks, result)
            spiking = spiking_model(folder)
            ticks = int(options.spiking_seconds / 0.001)
            for asked in (False, True) if options.spiking_runs else ():
                resyncs = []
                for _ in range(options.spiking_runs):
                    settings = {"tick_duration": 0.001}
                    if asked:
                        settings["priority"] = options.priority
                    hogs = start_hog(1)
                    try:
                        result = run(spiking, ticks, settings)
                    finally:
                        for p in hogs:
                            p.kill()
                            p.wait()
                    resyncs.append(result["resyncs"])
                    show("spiking_1k", True, asked, ticks, result)
                print(f"spiking_1k beside one busy loop, {'with' if asked else 'without'} "
                      f"the priority request: runs with no resynchronisation "
                      f"{resyncs.count(0)} of {len(resyncs)}")
    finally:
        simulator.terminate()
        simulator.wait(timeout=10)


if __name__ == "__main__":
    main()
