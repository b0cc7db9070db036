"""What recording costs the kernel: robot_320 recording every output every tick, vs not.

    python benchmarks/recording.py                 # 6 rounds of 20000 ticks each way
    python benchmarks/recording.py --rounds 3 --ticks 10000

The two kinds of run alternate (not recording, recording, ...) so that the machine's
changing speed hits both alike. It prints, per kind, the median wall time per tick and the
median CPU time per tick of the whole process (which includes the recorder's writer
thread, compressing on the other core), and the extra cost in percent. The kernel
thread's CPU time is the figure least disturbed by other work on a shared machine.
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
for _p in (HERE, ROOT):
    if _p not in sys.path:
        sys.path.insert(0, _p)

import models  # noqa: E402

import ikaros  # noqa: E402


def one_run(model: str, ticks: int, record_to: str | None) -> tuple[float, float, float, int]:
    """Wall, kernel-thread CPU and process CPU seconds per tick of ``ticks`` ticks, and the
    recorded file's bytes."""
    net = ikaros.load(model)
    net.run(ticks=100)                       # warm up
    recorder = net.record(record_to) if record_to else None
    wall, thread, cpu = time.perf_counter(), time.thread_time(), time.process_time()
    net.run(ticks=ticks)
    if recorder is not None:
        recorder.close()                     # the last chunk is part of the cost
    wall, thread = time.perf_counter() - wall, time.thread_time() - thread
    cpu = time.process_time() - cpu
    net.close()
    size = os.path.getsize(record_to) if record_to else 0
    return wall / ticks, thread / ticks, cpu / ticks, size


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rounds", type=int, default=6)
    p.add_argument("--ticks", type=int, default=20000)
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        model = models.robot_320(folder)
        h5 = os.path.join(folder, "run.h5")
        plain, recorded, size = [], [], 0
        for k in range(args.rounds):
            plain.append(one_run(model, args.ticks, None))
            recorded.append(one_run(model, args.ticks, h5))
            size = recorded[-1][3]
            print(f"round {k + 1}: {plain[-1][0] * 1e6:.1f} / {recorded[-1][0] * 1e6:.1f} "
                  f"us per tick", file=sys.stderr, flush=True)
        net = ikaros.load(model)
        columns = net.record(os.path.join(folder, "probe.h5"))._index.size
        net.close()
    def median_us(k):
        return [statistics.median(r[k] for r in runs) * 1e6 for runs in (plain, recorded)]
    print(f"robot_320, {args.rounds} rounds of {args.ticks} ticks; recording all "
          f"{columns} output values every tick ({size / args.ticks:.0f} bytes per tick "
          f"in the file, {columns * 4} raw)")
    print(f"{'':28} {'not recording':>14} {'recording':>10} {'extra':>8}")
    for k, label in enumerate(("wall time", "kernel thread CPU", "process CPU")):
        a, b = median_us(k)
        print(f"{label + ', us per tick':28} {a:>14.1f} {b:>10.1f} {(b / a - 1) * 100:>7.1f}%")


if __name__ == "__main__":
    main()
