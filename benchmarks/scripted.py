"""What a tick of a Python-scripted class costs (docs/python-scripts.md): the round trip
to its worker process, with a small input and a 640x480x3 image.

    python benchmarks/scripted.py                  # 5 rounds of 2000 / 200 ticks
    python benchmarks/scripted.py --rounds 3
    python benchmarks/scripted.py --startup-only   # the 8-module load and close only

The script copies its input to its output (``module.OUTPUT[...] = module.INPUT``), so a
tick sends the input through the pipe and the output back. The same model with a module
of the kernel's own process that does the same copy is timed too (alternating rounds);
the difference per tick is what the worker costs. It prints the medians in milliseconds,
and then how long a model of 8 scripted modules takes to load (its workers start) and to
close.
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)

import ikaros  # noqa: E402

SOURCE = '''import numpy as np
from ikaros.module import Module, Output, Parameter


class Source(Module):
    shape = Parameter("3", "the output's shape")
    OUTPUT = Output("random values")

    def set_sizes(self):
        self.set_output_shape("OUTPUT", tuple(int(s) for s in self.shape.split(",")))

    def init(self):
        self.OUTPUT[...] = np.random.default_rng(1).random(self.OUTPUT.shape)
'''

LOCAL = '''from ikaros.module import Input, Module, Output


class LocalCopy(Module):
    INPUT = Input("anything")
    OUTPUT = Output("the input", shape="INPUT.shape")

    def tick(self):
        self.OUTPUT[...] = self.INPUT
'''

IKC = '''<class name="ScriptCopy" python="script_copy.py">
    <input name="INPUT"/>
    <output name="OUTPUT" shape="INPUT.shape"/>
</class>
'''

SCRIPT = '''def tick(module):
    module.OUTPUT[...] = module.INPUT
'''

MODEL = '''<group name="Bench">
    <module class="Source" name="S" shape="{shape}"/>
    <module class="{copy}" name="Copy"/>
    <connection source="S.OUTPUT" target="Copy.INPUT"/>
</group>
'''


def per_tick(folder: str, copy: str, shape: str, ticks: int) -> float:
    path = os.path.join(folder, f"{copy}_{shape.replace(',', 'x')}.ikg")
    with open(path, "w") as f:
        f.write(MODEL.format(shape=shape, copy=copy))
    with ikaros.load(path, quiet=True) as net:
        net.run(20)
        start = time.perf_counter()
        net.run(ticks)
        return (time.perf_counter() - start) / ticks


STARTUP_MODULES = 8


def startup(folder: str) -> tuple[float, float]:
    """Seconds to load a model of STARTUP_MODULES scripted modules, and to close it."""
    path = os.path.join(folder, "startup.ikg")
    modules = "".join(f'<module class="ScriptCopy" name="Copy{i}"/>'
                      f'<connection source="S.OUTPUT" target="Copy{i}.INPUT"/>'
                      for i in range(STARTUP_MODULES))
    with open(path, "w") as f:
        f.write(f'<group name="Bench"><module class="Source" name="S"/>{modules}</group>')
    start = time.perf_counter()
    net = ikaros.load(path, quiet=True)
    loaded = time.perf_counter()
    net.close()
    return loaded - start, time.perf_counter() - loaded


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--startup-only", action="store_true", help="only the start-up time")
    opts = p.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        for name, text in (("Source.py", SOURCE), ("LocalCopy.py", LOCAL),
                           ("ScriptCopy.ikc", IKC), ("script_copy.py", SCRIPT)):
            with open(os.path.join(folder, name), "w") as f:
                f.write(text)
        ticked = () if opts.startup_only else (("3", 2000), ("480,640,3", 200))
        if ticked:
            print(f"{'input':>12} {'script ms/tick':>15} {'in-process ms/tick':>19} "
                  f"{'worker costs ms':>16}")
        for shape, ticks in ticked:
            script, local = [], []
            for _ in range(opts.rounds):
                local.append(per_tick(folder, "LocalCopy", shape, ticks))
                script.append(per_tick(folder, "ScriptCopy", shape, ticks))
            s, l = statistics.median(script) * 1e3, statistics.median(local) * 1e3
            print(f"{shape.replace(',', 'x'):>12} {s:15.3f} {l:19.3f} {s - l:16.3f}")
        times = [startup(folder) for _ in range(opts.rounds)]
        print(f"{STARTUP_MODULES} scripted modules: load "
              f"{statistics.median(t[0] for t in times):.3f} s, close "
              f"{statistics.median(t[1] for t in times):.3f} s")


if __name__ == "__main__":
    main()
