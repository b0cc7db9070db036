"""Links between kernels: round-trip latency, throughput, and a split model's speed-up.

    python benchmarks/links.py            # about a minute on a 2-core machine
    python benchmarks/links.py --quick

Runs from a checkout (the checkout goes on sys.path and on PYTHONPATH of the child kernels);
needs pyzmq. Every kernel is a separate process on this machine, linked over 127.0.0.1.

* round trip: kernel A publishes an array stamped with its tick (IPCServer) and waits for
  the same array to come back from kernel B (IPCClient -> IPCServer, an echo); one tick of A
  is one round trip. Median and 99th percentile in milliseconds, for 16 values and a
  640x480 image (float32).
* one way: A publishes as fast as it can, B takes every message in order; messages and
  megabytes per second received, and the share of A's messages B got (a publisher drops
  what a slow subscriber cannot take).
* split: a model with two heavy groups (pure-Python modules, which hold the GIL) run in one
  process, and with each heavy group in its own worker process (process="worker"); ticks
  per second of both and the speed-up, after checking that both give the same values.
"""
from __future__ import annotations

import argparse
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (ROOT, os.environ.get("PYTHONPATH"))
                                           if p)

import numpy as np  # noqa: E402

import ikaros  # noqa: E402

STAMP = '''
import numpy as np
from ikaros import Module, Output, Parameter


class Stamp(Module):
    """Fills OUTPUT (of shape ``shape``) with the tick number."""
    shape = Parameter("16", "the shape of OUTPUT")
    OUTPUT = Output("the tick, everywhere")

    def configure(self):
        self.set_output_shape("OUTPUT", tuple(int(s) for s in self.shape.split(",")))

    def tick(self):
        self.OUTPUT.fill(self.clock.tick)
'''

BUSY = '''
import numpy as np
from ikaros import Module, Input, Output, Parameter


class Busy(Module):
    """Pure-Python work that holds the GIL: OUTPUT = INPUT + (a sum of ``work`` terms)."""
    work = Parameter(20000, "loop iterations per tick", type="int")
    INPUT = Input("the signal")
    OUTPUT = Output("INPUT plus the sum", shape="INPUT.shape")

    def tick(self):
        s = 0
        for k in range(self.work):
            s += k % 7
        np.add(self.INPUT, s % 5, out=self.OUTPUT)
'''


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def write(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def start_kernel(model: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-q", model], cwd=ROOT,
                            stdout=subprocess.DEVNULL)


def round_trip(folder: str, shape: str, ticks: int) -> tuple[float, float]:
    out_port, back_port = free_port(), free_port()
    echo = write(folder, f"echo_{shape.replace(',', 'x')}.ikg", f'''<group name="Echo">
  <module class="IPCClient" name="In" port="{out_port}" shape="{shape}" mode="each"
          time_out_in_ms="1000"/>
  <module class="IPCServer" name="Out" port="{back_port}"/>
  <connection source="In.OUTPUT" target="Out.INPUT" delay="0"/>
</group>''')
    model = write(folder, "origin.ikg", f'''<group name="Origin">
  <module class="Stamp" name="S" shape="{shape}"/>
  <module class="IPCServer" name="Out" port="{out_port}"/>
  <module class="IPCClient" name="Back" port="{back_port}" shape="{shape}" mode="latest"
          time_out_in_ms="1000"/>
  <connection source="S.OUTPUT" target="Out.INPUT" delay="0"/>
</group>''')
    peer = start_kernel(echo)
    net = ikaros.load(model)
    try:
        deadline = time.monotonic() + 30
        in_step = 0
        while in_step < 20:             # until the echo runs in step with this kernel
            if time.monotonic() > deadline:
                raise SystemExit("the echo kernel did not answer")
            net.step()
            back = net.output("Back.OUTPUT")
            in_step = in_step + 1 if back.flat[0] == net.tick - 1 else 0
        times, misses = [], 0
        for _ in range(ticks):
            start = time.perf_counter()
            net.step()
            times.append(time.perf_counter() - start)
            misses += net.output("Back.OUTPUT").flat[0] != net.tick - 1
        if misses:
            print(f"  ({misses} of {ticks} round trips did not come back in time)",
                  file=sys.stderr)
        times.sort()
        return statistics.median(times) * 1e3, times[int(0.99 * (len(times) - 1))] * 1e3
    finally:
        net.close()
        peer.terminate()
        peer.wait()


def one_way(folder: str, shape: str, seconds: float) -> tuple[float, float, float]:
    port = free_port()
    model = write(folder, "source.ikg", f'''<group name="Source">
  <module class="Stamp" name="S" shape="{shape}"/>
  <module class="IPCServer" name="Out" port="{port}"/>
  <connection source="S.OUTPUT" target="Out.INPUT" delay="0"/>
</group>''')
    sink = write(folder, "sink.ikg", f'''<group name="Sink">
  <module class="IPCClient" name="In" port="{port}" shape="{shape}" mode="each"
          time_out_in_ms="2000"/>
</group>''')
    script = (f"import ikaros, time, sys\nnet = ikaros.load({sink!r})\n"
              f"print('ready', flush=True)\ngot, first = 0, None\n"
              f"while True:\n    net.step()\n"
              f"    if net.output('In.TIME_OUT')[0]:\n        if first is not None: break\n"
              f"        continue\n"
              f"    got += 1\n    first = first or time.perf_counter()\n"
              f"    last = time.perf_counter()\n"
              f"print(got, last - first, flush=True)\nnet.close()\n")
    sink_process = subprocess.Popen([sys.executable, "-c", script], cwd=ROOT,
                                    stdout=subprocess.PIPE, text=True)
    sink_process.stdout.readline()
    net = ikaros.load(model)
    try:
        time.sleep(0.5)                 # the subscription reaches the publisher
        end = time.perf_counter() + seconds
        while time.perf_counter() < end:
            net.run(ticks=10)
        got, received_in = sink_process.stdout.readline().split()
    finally:
        net.close()
        sink_process.wait(30)
    got, received_in = int(got), float(received_in)
    size = int(np.prod([int(s) for s in shape.split(",")])) * 4
    rate = (got - 1) / received_in if received_in > 0 else float("nan")
    return rate, rate * size / 1e6, got / net.tick


def split_model(folder: str, work: int, modules: int) -> str:
    def heavy(name):
        chain = "\n".join(f'    <module class="Busy" name="B{k}" work="@work"/>'
                          for k in range(modules))
        links = "\n".join(f'    <connection source="B{k}.OUTPUT" target="B{k + 1}.INPUT" '
                          f'delay="0"/>' for k in range(modules - 1))
        return f'''  <group name="{name}" process="@where">
    <input name="IN"/>
    <output name="OUT"/>
{chain}
{links}
    <connection source="IN" target="B0.INPUT" delay="0"/>
    <connection source="B{modules - 1}.OUTPUT" target="OUT" delay="0"/>
  </group>'''
    return write(folder, "split.ikg", f'''<group name="Split" where="worker" work="{work}">
  <module class="Sweep" name="Src" min="0" max="1000" step="1"/>
{heavy("Left")}
{heavy("Right")}
  <module class="Add" name="Sum"/>
  <connection source="Src.OUTPUT" target="Left.IN"/>
  <connection source="Src.OUTPUT" target="Right.IN"/>
  <connection source="Left.OUT" target="Sum.INPUT1"/>
  <connection source="Right.OUT" target="Sum.INPUT2"/>
</group>''')


def split_speed(folder: str, ticks: int, work: int, modules: int, rounds: int):
    """Median ticks/s in one process and split, over alternating rounds; whether the two
    gave the same values."""
    model = split_model(folder, work, modules)
    rates = {"": [], "worker": []}
    values = {}
    for _ in range(rounds):
        for where in rates:
            net = ikaros.load(model, where=where)
            try:
                trace = []
                net.run(ticks=3)
                start = time.perf_counter()
                for _ in range(ticks):
                    net.step()
                    trace.append(float(net.output("Sum.OUTPUT")[0]))
                rates[where].append(ticks / (time.perf_counter() - start))
                values[where] = trace
            finally:
                net.close()
    return (statistics.median(rates[""]), statistics.median(rates["worker"]),
            values[""] == values["worker"])


def two_core_check(steps: int = 3_000_000) -> float:
    """How much faster two pure-Python processes finish than one after the other, now: the
    most a split into two processes can gain on this machine at this moment."""
    code = f"s = 0\nfor k in range({steps}): s += k % 7"
    def run(n):
        start = time.perf_counter()
        procs = [subprocess.Popen([sys.executable, "-c", code]) for _ in range(n)]
        for proc in procs:
            proc.wait()
        return time.perf_counter() - start
    return 2 * run(1) / run(2)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="fewer ticks")
    opts = p.parse_args()
    n = 200 if opts.quick else 1000
    with tempfile.TemporaryDirectory() as folder:
        write(folder, "Stamp.py", STAMP)
        write(folder, "Busy.py", BUSY)
        print("| Link | 16 values | 640x480 image |\n|---|---|---|")
        rt = [round_trip(folder, s, n) for s in ("16", "480,640")]
        print(f"| round trip, ms (median / p99) | {rt[0][0]:.3f} / {rt[0][1]:.3f} | "
              f"{rt[1][0]:.2f} / {rt[1][1]:.2f} |")
        ow = [one_way(folder, s, 1.0 if opts.quick else 3.0) for s in ("16", "480,640")]
        print(f"| one way, messages/s (MB/s) | {ow[0][0]:.0f} ({ow[0][1]:.2f}) | "
              f"{ow[1][0]:.0f} ({ow[1][1]:.0f}) |")
        print(f"| one way, share received | {ow[0][2]:.0%} | {ow[1][2]:.0%} |")
        print("\n| Split model: two groups of 4 pure-Python modules | one process, "
              "ticks/s | a worker per group, ticks/s | speed-up | same values |\n"
              "|---|---|---|---|---|")
        parallel = two_core_check()
        for work in (20000, 100000):
            one, two, same = split_speed(folder, 20 if opts.quick else 60, work, 4,
                                         1 if opts.quick else 3)
            print(f"| {work} loop steps per module and tick | {one:.1f} | {two:.1f} | "
                  f"{two / one:.2f}x | {'yes' if same else 'NO'} |")
        print(f"\ntwo-core check: two pure-Python processes at once finish {parallel:.2f}x "
              f"as fast as one after the other (2.00x on two idle cores)")


if __name__ == "__main__":
    main()
