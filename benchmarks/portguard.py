"""What the check that no module replaced a port array costs per tick (kernel/portguard.py):
robot_320 (``models.py``) run with the check and without it, alternating.

    python benchmarks/portguard.py                       # as the model loads by default
    IKAROS_COMPILED=0 python benchmarks/portguard.py     # the NumPy kernel

It prints the ports watched (those of modules whose Python tick runs), the time of one
check (timeit), and the median time per tick of 5 rounds of 2000 ticks each way.
"""
from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
import timeit

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.dirname(HERE)]

import models  # noqa: E402

import ikaros  # noqa: E402


def main() -> None:
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as folder:
        net = ikaros.load(models.robot_320(folder), quiet=True)
    net.run(ticks=200)
    net.wait_compiled(timeout=120)
    net.run(ticks=200)
    guard = net.plan.guard
    watched = len(guard) if guard is not None else 0
    check = min(timeit.repeat(guard.check, number=2000, repeat=5)) / 2000 if guard else 0.0

    def per_tick(ticks: int = 2000) -> float:
        start = time.perf_counter()
        net.run(ticks=ticks)
        return (time.perf_counter() - start) / ticks
    on, off = [], []
    for _ in range(5):
        net.plan.guard = guard
        on.append(per_tick())
        net.plan.guard = None
        off.append(per_tick())
    net.close()
    print(f"robot_320, {net.compiled_modules} compiled modules: {watched} ports watched; "
          f"one check {check * 1e6:.2f} us; per tick {statistics.median(on) * 1e6:.1f} us "
          f"with the check, {statistics.median(off) * 1e6:.1f} us without (load average "
          f"{load:.2f} before, {os.getloadavg()[0]:.2f} after)")


if __name__ == "__main__":
    main()
