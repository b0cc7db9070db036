"""Models built in code: the time to make, build, save, load and apply a chain of modules.

    PYTHONPATH=. python benchmarks/builder.py [MODULES]     (default 1000)
"""
from __future__ import annotations

import os
import sys
import tempfile
import time

import ikaros


def main(count: int = 1000) -> None:
    with tempfile.TemporaryDirectory() as folder:
        t0 = time.perf_counter()
        model = ikaros.Group("Chain")
        previous = model.module("Constant", "C", data="1, 2, 3")
        for i in range(count):
            module = model.module("Scale", f"S{i}", factor=1.001)
            model.connect(previous.OUTPUT, module.INPUT, delay=0)
            previous = module
        t1 = time.perf_counter()
        net = model.build()
        t2 = time.perf_counter()
        path = os.path.join(folder, "chain.ikg")
        model.save(path)
        t3 = time.perf_counter()
        ikaros.load(path).close()
        t4 = time.perf_counter()
        model.module("Constant", "Extra", data="0")
        net = net.apply(model)
        t5 = time.perf_counter()
        net.close()
    print(f"{count + 1} modules, {count} connections: make in code {t1 - t0:.3f} s, "
          f"build {t2 - t1:.3f} s, save {t3 - t2:.3f} s, load the saved file "
          f"{t4 - t3:.3f} s, apply one added module {t5 - t4:.3f} s")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1000)
