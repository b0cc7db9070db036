"""Vision benchmark: a colour camera through a six-stage pipeline, in ikaros and in plain OpenCV.

The pipeline is the overhead tracker's: colour transform (RGB -> rgI), Gaussian filter (each
of the three planes), colour classifier, dilate, spatial clustering, and an overlay that
draws the cluster on a copy of the camera image. The camera is SyntheticCamera (three
moving discs), at 640 x 480 and at 1280 x 720. The reference is the same six stages called
directly in OpenCV and NumPy on the same frames (benchmarks/_vision_direct.py says what
each call does); before timing, the script checks that the reference gives the modules'
values, bit for bit, tick by tick. For each size it prints:

* the pipeline's ms per frame in ikaros (the network's tick minus the camera module's,
  profiling on) and directly, in rounds in which each frame goes first through the network
  and then through the direct calls (so both see the same load from moment to moment), and
  the ratio ikaros / direct of each round: the median and range over the rounds;
* per stage, the modules' mean ms beside the direct calls' ms, and the ratio;
* the camera's ms, the kernel's own time per tick (the tick minus the module ticks) and
  the whole tick;
* real time at 30 Hz (tick_duration 1/30 s), camera included, for each priority request
  of ``--priorities`` (default ``off,fifo``): the lag's mean, 99th percentile and maximum
  over ``--seconds``, whether every tick started within one frame (and none was
  skipped), and the longest tick on the wall clock and on the tick thread's CPU clock (a
  tick that took a frame of CPU cannot keep up, whatever its priority);
* with ``--web-ui``: also the lag of the same run with the web UI server up and a client
  subscribed to two images (the camera and the overlay, as JPEG) polling as fast as the
  server lets it, and the frames per second the client got.

    python benchmarks/vision.py                       # about three minutes
    python benchmarks/vision.py --sizes 1280x720 --web-ui
    python benchmarks/vision.py --rounds 3 --ticks 30 --sizes 640x480
"""
from __future__ import annotations

import argparse
import contextlib
import multiprocessing
import os
import statistics
import sys
import tempfile
import time
import types
from concurrent.futures import ProcessPoolExecutor

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

import cv2  # noqa: E402

import ikaros  # noqa: E402
from benchmarks._vision_direct import DirectPipeline  # noqa: E402
from ikaros.kernel import execution  # noqa: E402
from ikaros.kernel.threadpools import default_threads  # noqa: E402

OVERLAY = '''
import numpy as np
import cv2
from ikaros import Input, Module, Output


class Overlay(Module):
    """Copies the image and draws a circle at each position (x, y in 0..1)."""
    INPUT = Input("the colour image")
    POSITIONS = Input("rows (x, y)")
    OUTPUT = Output("the image with the circles", shape="INPUT.shape")

    def tick(self):
        self.OUTPUT[...] = self.INPUT
        rows, cols = self.INPUT.shape[1:]
        for x, y in self.POSITIONS.reshape(-1, 2):
            centre = (int(x * cols), int(y * rows))
            for plane in self.OUTPUT:
                cv2.circle(plane, centre, 20, 1.0, 2)
'''

MODEL = '''<?xml version="1.0"?>
<group name="VisionBenchmark" tick_duration="{tick}">
    <module class="SyntheticCamera" name="Camera" size_x="{cols}" size_y="{rows}" blobs="3" />
    <module class="ColorTransform" name="Chromaticity" transform="RGB->rgI" ignore_transform="no" />
    <module class="GaussianFilter" name="BlurR" sigma="1" kernel_size="5" />
    <module class="GaussianFilter" name="BlurG" sigma="1" kernel_size="5" />
    <module class="GaussianFilter" name="BlurI" sigma="1" kernel_size="5" />
    <module class="ColorClassifier" name="Classifier" color="117" width="15" diagnostics="no" />
    <module class="Dilate" name="Dilate" />
    <module class="SpatialClustering" name="Clustering" threshold="0.5" cluster_radius="0.05"
                min_cluster_area="0.001" />
    <module class="Overlay" name="Overlay" />
    <connection source="Camera.OUTPUT" target="Chromaticity.INPUT" delay="0" />
    <connection source="Chromaticity.OUTPUT0" target="BlurR.INPUT" delay="0" />
    <connection source="Chromaticity.OUTPUT1" target="BlurG.INPUT" delay="0" />
    <connection source="Chromaticity.OUTPUT2" target="BlurI.INPUT" delay="0" />
    <connection source="BlurR.OUTPUT" target="Classifier.R" delay="0" />
    <connection source="BlurG.OUTPUT" target="Classifier.G" delay="0" />
    <connection source="BlurI.OUTPUT" target="Classifier.I" delay="0" />
    <connection source="Classifier.OUTPUT" target="Dilate.INPUT" delay="0" />
    <connection source="Dilate.OUTPUT" target="Clustering.INPUT" delay="0" />
    <connection source="Camera.OUTPUT" target="Overlay.INPUT" delay="0" />
    <connection source="Clustering.OUTPUT" target="Overlay.POSITIONS" delay="0" />
</group>
'''

FRAME_MS = 1000 / 30
# the modules of each stage in the model
STAGE_MODULES = {"colour transform": ["Chromaticity"], "Gaussian filter": ["BlurR", "BlurG",
                 "BlurI"], "classifier": ["Classifier"], "dilate": ["Dilate"],
                 "clustering": ["Clustering"], "overlay": ["Overlay"]}


def write_model(folder: str, rows: int, cols: int) -> str:
    with open(os.path.join(folder, "Overlay.py"), "w") as f:
        f.write(OVERLAY)
    path = os.path.join(folder, f"vision_{cols}x{rows}.ikg")
    with open(path, "w") as f:
        f.write(MODEL.format(rows=rows, cols=cols, tick=1 / 30))
    return path


def check(net, pipeline: DirectPipeline, ticks: int) -> None:
    """The direct pipeline, fed each tick with the camera's frame, gives every stage's
    output as the network does, bit for bit; AssertionError otherwise."""
    for tick in range(ticks):
        net.step()
        frame = net.output("Camera.OUTPUT")
        for _, stage in pipeline.stages():
            stage(frame)
        for name, value in pipeline.results().items():
            if not np.array_equal(net.output(name), value):
                raise AssertionError(f"tick {tick}: {name} differs from the direct call")


def module_seconds(net) -> dict:
    """Each module's time so far (profiling on), in seconds."""
    return {m["module"]: m["mean"] * m["count"] for m in net.module_figures()}


CLOCKS = {"wall": time.perf_counter, "CPU": time.thread_time}


@contextlib.contextmanager
def profiler_clock(clock):
    """The kernel's module profiler reads ``clock`` instead of the wall clock: with
    time.thread_time it gives the CPU time of the tick's thread (all of a module's work
    when OpenCV runs in the calling thread)."""
    saved = execution.time
    execution.time = types.SimpleNamespace(perf_counter=clock)
    try:
        yield
    finally:
        execution.time = saved


def one_round(net, stages: list, ticks: int, clock) -> tuple[dict, dict]:
    """``ticks`` frames, each through the network (one tick, the modules profiled) and then
    through the direct calls; the ikaros figures and the direct ones, in ms per frame."""
    before, ticked = module_seconds(net), 0.0
    spent = dict.fromkeys(STAGE_MODULES, 0.0)
    for _ in range(ticks):
        start = clock()
        net.step()
        ticked += clock() - start
        frame = net.buffer_array("Camera.OUTPUT")
        for name, stage in stages:
            start = clock()
            stage(frame)
            spent[name] += clock() - start
    after = module_seconds(net)
    ms = {m: (after[m] - before[m]) / ticks * 1000 for m in after}
    total = ticked / ticks * 1000
    mine = {"total": total, "camera": ms["Camera"], "pipeline": total - ms["Camera"],
            "kernel": total - sum(ms.values()),
            "stages": {k: sum(ms[m] for m in v) for k, v in STAGE_MODULES.items()}}
    ref = {k: v / ticks * 1000 for k, v in spent.items()}
    return mine, {"pipeline": sum(ref.values()), "stages": ref}


def alternating(path: str, rows: int, cols: int, a) -> dict:
    """Rounds of ``a.ticks`` frames, each frame through the network and then through the
    direct calls, so that both see the same load from moment to moment; a round on the wall
    clock and one on the CPU clock by turns. Per clock, per round: (ikaros, direct)."""
    pipeline = DirectPipeline(rows, cols)
    rounds = {name: [] for name in CLOCKS}
    with ikaros.load(path) as net:
        print(f"{cols}x{rows}: checking that the direct calls give the modules' values",
              file=sys.stderr)
        check(net, pipeline, 8)
        net.profiling = True
        for k in range(a.rounds):
            print(f"{cols}x{rows}: round {k + 1} of {a.rounds} (load average "
                  f"{load_average()})", file=sys.stderr)
            for name, clock in CLOCKS.items():
                with profiler_clock(clock):
                    rounds[name].append(one_round(net, pipeline.stages(), a.ticks, clock))
    return rounds


class TickTimes:
    """A tick hook (in the tick thread): each tick's wall time and the tick thread's CPU
    time since the previous tick's hooks (the tick's work and the hooks after it)."""

    def __init__(self, net):
        self.timing = net.timing
        self.wall: list[float] = []
        self.cpu: list[float] = []
        self._cpu = None

    def __call__(self) -> None:
        cpu = time.thread_time()
        if self._cpu is not None:
            self.cpu.append(cpu - self._cpu)
        self._cpu = cpu
        self.wall.append(self.timing.last_spent)

    def mark(self) -> tuple[int, int]:
        return len(self.wall), len(self.cpu)

    def longest(self, since: tuple[int, int]) -> tuple[float, float]:
        """The longest tick since ``mark()`` in ms: wall, CPU."""
        return (max(self.wall[since[0]:], default=0.0) * 1e3,
                max(self.cpu[since[1]:], default=0.0) * 1e3)


def real_time(path: str, priority: str, seconds: float, web_ui: bool) -> dict:
    """Real time at 30 Hz (camera included) with the tick thread's ``priority`` request:
    the lag (mean, p99, max in ms) over ``seconds`` without the web UI, then, with
    ``web_ui``, over ``seconds`` with the web UI server up and a client polling two images
    (JPEG) as fast as the server lets it, and the frames per second the client got; and the
    longest tick of each phase (wall and CPU ms)."""
    from benchmarks.webui import lag_figures, serve_in_thread, start_client
    from ikaros.module import WARNING

    net = ikaros.load(path, priority=priority)
    net.log_level = WARNING
    ctrl = net.controller
    ticks = TickTimes(net)
    ctrl.tick_hooks.append(ticks)
    ctrl.start("realtime")
    server = proc = None
    try:
        time.sleep(1.0)                                       # warm up
        resyncs, since = net.figures()["resyncs"], ticks.mark()
        out = {"alone": lag_figures(net, seconds), "resyncs": {}, "longest": {}}
        out["resyncs"]["alone"] = net.figures()["resyncs"] - resyncs
        out["longest"]["alone"] = ticks.longest(since)
        if web_ui:
            server, thread, port = serve_in_thread(net)
            proc, go, stop, quit_, frames, connected = start_client(
                port, ["Camera.OUTPUT", "Overlay.OUTPUT"], "jpeg")
            go.set()
            if not connected.wait(30):
                raise RuntimeError("the web UI client did not connect")
            time.sleep(0.5)
            f0, t0 = frames.value, time.perf_counter()
            resyncs, since = net.figures()["resyncs"], ticks.mark()
            out["shown"] = lag_figures(net, seconds)
            out["resyncs"]["shown"] = net.figures()["resyncs"] - resyncs
            out["longest"]["shown"] = ticks.longest(since)
            out["fps"] = (frames.value - f0) / (time.perf_counter() - t0)
        out["priority"] = (net.figures().get("priority") or {}).get("tick_thread") or "normal"
    finally:
        if proc is not None:
            stop.set()
            quit_.set()
            proc.join(10)
        if server is not None:
            server.should_exit = True
            thread.join(10)
        ctrl.stop()
        ctrl.join(10)
        net.close()
    return out


def spread(values) -> str:
    """median (least-most) of a list of figures."""
    return (f"{statistics.median(values):.2f} ({min(values):.2f}-{max(values):.2f})"
            if len(values) > 1 else f"{values[0]:.2f}")


def load_average() -> str:
    return ", ".join(f"{v:.1f}" for v in os.getloadavg())


def measure(path: str, rows: int, cols: int, a) -> dict:
    """The alternating rounds, then the real-time runs."""
    rounds = alternating(path, rows, cols, a)
    real = {}
    for priority in a.priorities.split(","):
        print(f"{cols}x{rows}: real time at 30 Hz, priority {priority}", file=sys.stderr)
        # a process of its own: a priority request holds for the process that made it
        with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
            real[priority] = pool.submit(real_time, path, priority, a.seconds,
                                         a.web_ui).result()
    return {"rounds": rounds, "real": real}


def table_header(header: str) -> None:
    print(header)
    print("-" * len(header))


def report(results: dict, a) -> None:
    print(f"\nVision pipeline: {a.rounds} rounds of {a.ticks} frames, each frame through ikaros "
          f"and then directly; a camera frame every {FRAME_MS:.1f} ms (30 Hz); "
          f"{os.cpu_count()} cores, OpenCV's threads "
          f"{a.opencv_threads}; load average {load_average()} at the end\n")
    print("ms per frame: median (least-most) over the rounds; ratio: ikaros / direct, per "
          "round; wall: elapsed time, CPU: the thread's CPU time\n")
    table_header(f"{'size':>10} {'clock':>5} {'stage':>17} {'ikaros ms':>20} "
                 f"{'direct ms':>20} {'ratio':>18}")
    for size, r in results.items():
        for clock, pairs in r["rounds"].items():
            for name in ["pipeline"] + list(STAGE_MODULES):
                mine = [b["pipeline"] if name == "pipeline" else b["stages"][name]
                        for b, _ in pairs]
                ref = [d["pipeline"] if name == "pipeline" else d["stages"][name]
                       for _, d in pairs]
                ratio = [m / d for m, d in zip(mine, ref)]
                print(f"{size:>10} {clock:>5} {name:>17} {spread(mine):>20} {spread(ref):>20} "
                      f"{spread(ratio):>18}")
            for name in ("camera", "kernel", "total"):
                print(f"{size:>10} {clock:>5} {name.replace('total', 'tick'):>17} "
                      f"{spread([b[name] for b, _ in pairs]):>20}")
    print(f"\nReal time at 30 Hz, camera included, {a.seconds:g} s per phase: lag in ms "
          f"(mean, p99, max); within a frame: every tick started less than "
          f"{FRAME_MS:.1f} ms late and none was skipped (resynchronised); the longest tick "
          f"in ms on the wall clock and on the tick thread's CPU clock\n")
    table_header(f"{'size':>10} {'priority':>10} {'phase':>17} {'lag mean':>9} {'p99':>7} "
                 f"{'max':>7} {'frames/s':>9} {'within a frame':>15} {'tick wall':>10} "
                 f"{'tick CPU':>9}")
    for size, r in results.items():
        for asked, run in r["real"].items():
            phases = [("no web UI", "alone")]
            if "shown" in run:
                phases.append(("web UI, 2 images", "shown"))
            for phase, key in phases:
                mean, p99, most = run[key]
                fps = f"{run['fps']:.1f}" if key == "shown" else ""
                kept = most < FRAME_MS and run["resyncs"][key] == 0
                wall, cpu = run["longest"][key]
                print(f"{size:>10} {asked:>10} {phase:>17} {mean:>9.2f} {p99:>7.2f} "
                      f"{most:>7.2f} {fps:>9} {'yes' if kept else 'no':>15} {wall:>10.1f} "
                      f"{cpu:>9.1f}")
            print(f"{size:>10} {asked:>10} granted: {run['priority']}; resynchronised "
                  f"{sum(run['resyncs'].values())} times")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ticks", type=int, default=60, help="frames per round (60)")
    p.add_argument("--rounds", type=int, default=5, help="alternating rounds (5)")
    p.add_argument("--sizes", default="640x480,1280x720", help="COLSxROWS,...")
    p.add_argument("--web-ui", action="store_true", help="also run in real time with the web "
                   "UI showing two images")
    p.add_argument("--seconds", type=float, default=10.0,
                   help="length of each real-time phase (10)")
    p.add_argument("--opencv-threads", type=int, default=default_threads(),
                   help="OpenCV's threads in the timed rounds (default: as a real-time run "
                   "sizes them, the cores less one: %(default)s)")
    p.add_argument("--priorities", default="off,fifo",
                   help="the tick thread's priority requests of the real-time runs")
    a = p.parse_args(argv)
    cv2.setNumThreads(a.opencv_threads)
    print(f"load average at the start {load_average()}", file=sys.stderr)
    results = {}
    with tempfile.TemporaryDirectory() as folder:
        for size in a.sizes.split(","):
            cols, rows = (int(v) for v in size.split("x"))
            results[size] = measure(write_model(folder, rows, cols), rows, cols, a)
    report(results, a)


if __name__ == "__main__":
    main()
