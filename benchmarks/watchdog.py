"""What the task watchdog (top-group task_timeout) costs the kernel: robot_320 with and
without it.

    python benchmarks/watchdog.py                  # 6 rounds of 300000 ticks each way
    python benchmarks/watchdog.py --rounds 3 --ticks 100000
    IKAROS_COMPILED=0 python benchmarks/watchdog.py      # with the NumPy kernel

The two kinds of run alternate (off, on, ...) so that the machine's changing speed hits
both alike. Each run loads the model, waits for the compiled tick (when numba is
installed) and runs 100 ticks before it is timed. It prints, per kind, the median wall time
and kernel-thread CPU time per tick, and the extra in percent with its range over the
rounds. The watchdog adds nothing to a tick; what it costs is its own thread's look at the
threads' stacks every 0.1 s (with ``task_timeout`` >= 1 s), which shows in the process's
CPU time, not the kernel thread's.
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


def one_run(model: str, ticks: int, timeout: str | None) -> tuple[float, float, float]:
    """Seconds per tick of ``ticks`` ticks: wall time, kernel-thread CPU, process CPU."""
    net = ikaros.load(model, **({"task_timeout": timeout} if timeout else {}))
    net.wait_compiled()
    net.run(100)
    wall, cpu, process = time.perf_counter(), time.thread_time(), time.process_time()
    net.run(ticks)
    out = ((time.perf_counter() - wall) / ticks, (time.thread_time() - cpu) / ticks,
           (time.process_time() - process) / ticks)
    net.close()
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=6)
    parser.add_argument("--ticks", type=int, default=300000)
    parser.add_argument("--timeout", default="5", help="task_timeout of the runs with it")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        model = models.robot_320(folder)
        off, on = [], []
        for _ in range(args.rounds):
            off.append(one_run(model, args.ticks, None))
            on.append(one_run(model, args.ticks, args.timeout))
    print(f"robot_320, {args.rounds} rounds of {args.ticks} ticks; task_timeout="
          f"{args.timeout} vs unset")
    print(f"{'us per tick':24} {'unset':>10} {'set':>10} {'extra':>8}")
    for k, label in enumerate(("wall time", "kernel thread CPU", "process CPU")):
        a, b = (statistics.median(r[k] for r in runs) * 1e6 for runs in (off, on))
        print(f"{label:24} {a:>10.2f} {b:>10.2f} {(b / a - 1) * 100:>7.1f}%")
    extra = sorted((b[0] / a[0] - 1) * 100 for a, b in zip(off, on))
    print(f"extra wall time, round by round: {extra[0]:.1f} to {extra[-1]:.1f} %")


if __name__ == "__main__":
    main()
