"""What recording costs the kernel: robot_320 recording every output every tick, vs not.

    python benchmarks/recording.py                 # 6 rounds of 20000 ticks each way
    python benchmarks/recording.py --rounds 3 --ticks 10000
    IKAROS_COMPILED=0 python benchmarks/recording.py      # with the NumPy kernel
    python benchmarks/recording.py --flush 1 --flush 0.1 --flush 0.01   # flush intervals

Each run loads the model, waits for the compiled tick (when numba is installed) and runs
100 ticks before it is timed. The two kinds of run alternate (not recording, recording,
...) so that the machine's changing speed hits both alike. It prints, per kind, the median
per tick of: the wall time of the run (the kernel thread's time: the cost), the kernel
thread's CPU time (the figure least disturbed by other work on a shared machine), the CPU
time of the whole process (with the recorder's writer thread, compressing on the other
core), and the wall time with the recording's close (writing what is left); and the extra
cost in percent, with the range over the rounds of the first figure. With ``--flush`` (one
or more flush intervals in seconds, default 1) each round records once per interval.
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


def one_run(model: str, ticks: int, record_to: str | None, flush: float = 1.0) -> tuple:
    """Seconds per tick of ``ticks`` ticks: wall time and kernel-thread CPU of the run,
    process CPU and wall time with the recording's close; the recorded file's bytes; and
    the number of compiled modules."""
    net = ikaros.load(model)
    net.run(ticks=100)                       # warm up
    compiled = net.wait_compiled(timeout=120)
    net.run(ticks=100)
    recorder = net.record(record_to, flush_seconds=flush) if record_to else None
    wall, thread, cpu = time.perf_counter(), time.thread_time(), time.process_time()
    net.run(ticks=ticks)
    run_wall, thread = time.perf_counter() - wall, time.thread_time() - thread
    if recorder is not None:
        recorder.close()                     # writing what is left
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    net.close()
    size = os.path.getsize(record_to) if record_to else 0
    return (run_wall / ticks, thread / ticks, cpu / ticks, wall / ticks), size, compiled


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rounds", type=int, default=6)
    p.add_argument("--ticks", type=int, default=20000)
    p.add_argument("--flush", type=float, action="append", metavar="SECONDS",
                   help="a flush interval to record with (repeatable; default 1)")
    args = p.parse_args()
    flushes = args.flush or [1.0]
    with tempfile.TemporaryDirectory() as folder:
        model = models.robot_320(folder)
        h5 = os.path.join(folder, "run.h5")
        plain, recorded, size = [], {f: [] for f in flushes}, 0
        load = os.getloadavg()[0]
        for k in range(args.rounds):
            figures, _, compiled = one_run(model, args.ticks, None)
            plain.append(figures)
            for flush in flushes:
                figures, size, _ = one_run(model, args.ticks, h5, flush)
                recorded[flush].append(figures)
            print(f"round {k + 1}: {plain[-1][0] * 1e6:.1f} / " + " / ".join(
                f"{recorded[f][-1][0] * 1e6:.1f}" for f in flushes) + " us per tick",
                file=sys.stderr, flush=True)
        net = ikaros.load(model)
        columns = net.record(os.path.join(folder, "probe.h5"))._index.size
        net.close()
    kernel = f"the compiled tick ({compiled} modules)" if compiled else "the NumPy kernel"
    print(f"robot_320 with {kernel}, {args.rounds} rounds of {args.ticks} ticks; recording "
          f"all {columns} output values every tick ({size / args.ticks:.0f} bytes per tick "
          f"in the file, {columns * 4} raw); load average {load:.2f} before, "
          f"{os.getloadavg()[0]:.2f} after")
    for flush in flushes:
        report(plain, recorded[flush], flush)


def report(plain: list, recorded: list, flush: float) -> None:
    """The medians per tick of the figures of one_run, not recording and recording."""
    def median_us(k):
        return [statistics.median(r[k] for r in runs) * 1e6 for runs in (plain, recorded)]
    print(f"\nflushed every {flush:g} s")
    print(f"{'us per tick':32} {'not recording':>14} {'recording':>10} {'extra':>8}")
    for k, label in enumerate(("wall time of the run (the cost)", "kernel thread CPU",
                               "process CPU, with close", "wall time, with close")):
        a, b = median_us(k)
        print(f"{label:32} {a:>14.2f} {b:>10.2f} {(b / a - 1) * 100:>7.1f}%")
    extra = sorted((r[0] / p[0] - 1) * 100 for p, r in zip(plain, recorded))
    print(f"extra wall time of the run, round by round: {extra[0]:.1f} to {extra[-1]:.1f} %")


if __name__ == "__main__":
    main()
