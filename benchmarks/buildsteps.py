"""The CPU time of each start-up step of ``ikaros.load`` on a chain of Scale modules, delay 0
(chain_N_d0 of ``models.py``), in one process: the median of several loads, after one small
load for the imports and the class discovery.

    python benchmarks/buildsteps.py [--modules 10000] [--loads 5]

To compare two versions, run it alternately in fresh processes with each checkout first on
the path (``PYTHONPATH=/path/to/other/checkout python benchmarks/buildsteps.py``): on a
shared machine the CPU time is steadier than the wall time, but it still drifts, so only
turns taken close together compare.
"""
from __future__ import annotations

import argparse
import gc
import os
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import models  # noqa: E402

import ikaros  # noqa: E402
from ikaros.kernel import startup  # noqa: E402


class _CPUClock:
    """Stands for the time module in kernel/startup.py, so the steps are timed in CPU time."""
    perf_counter = staticmethod(time.process_time)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--modules", type=int, default=10000)
    parser.add_argument("--loads", type=int, default=5)
    args = parser.parse_args()
    startup.time = _CPUClock
    with tempfile.TemporaryDirectory() as folder:
        ikaros.load(models.chain(folder, 10, 1)).close()
        path = models.chain(folder, args.modules, 0)
        rows = []
        for _ in range(args.loads):
            cpu, wall = time.process_time(), time.perf_counter()
            net = ikaros.load(path)
            cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
            rows.append({"CPU": cpu, "wall": wall, **dict(net.startup.steps)})
            net.close()
            del net
            gc.collect()
    print(f"ikaros.load of chain_{args.modules}_d0, median of {args.loads} loads, ms "
          f"(load average {os.getloadavg()[0]:.1f}; {ikaros.__file__})")
    for key in rows[0]:
        print(f"  {key:24s} {statistics.median(r[key] for r in rows) * 1e3:8.1f}")


if __name__ == "__main__":
    main()
