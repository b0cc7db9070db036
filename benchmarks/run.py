"""Benchmark suite for ikaros for Python.

    python benchmarks/run.py            # full run (about 10 minutes on a 2-core machine)
    python benchmarks/run.py --quick    # short run (about 1-2 minutes)
    python benchmarks/run.py --only robot_320 --only 'chain_1000_*' --only jitter

Selectable names: robot_320, chain_{10,100,1000,10000}_d{0,1}, matrix_chain_d{0,1}, pipelines_t{1,2},
jitter, soak (shell-style patterns allowed; a name also selects what starts with NAME_).
See benchmarks/README.md for what each figure means.
"""
from __future__ import annotations

import argparse
import fnmatch
import functools
import gc
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
for _p in (HERE, ROOT):        # models.py next to this file; ikaros from this checkout
    if _p not in sys.path:
        sys.path.insert(0, _p)

import models  # noqa: E402

# Child processes find the package in this checkout whether or not it is installed.
CHILD_ENV = dict(os.environ)
CHILD_ENV["PYTHONPATH"] = ROOT + (os.pathsep + os.environ["PYTHONPATH"]
                                  if os.environ.get("PYTHONPATH") else "")

# The child's own peak RSS (VmHWM): wait4's ru_maxrss of a child started from a large parent
# (as this one is once numba and big models are loaded) starts at the parent's size.
PEAK_CODE = ("print(next(int(l.split()[1]) for l in open('/proc/self/status') "
             "if l.startswith('VmHWM:')) / 1024)")

# The brief's start-up command, plus (after tick 0) a timestamp on the system-wide
# monotonic clock and an optional number of further ticks so that the process's peak RSS
# covers a run, not just the build.
STARTUP_CODE = ("import ikaros,sys; net=ikaros.load(sys.argv[1]); net.step(); "
                "import time; print(time.monotonic(), flush=True); "
                "n=int(sys.argv[2]); n and net.run(ticks=n); " + PEAK_CODE)

TRACED_CODE = ("import ikaros,sys,tracemalloc,json; tracemalloc.start(); "
               "net=ikaros.load(sys.argv[1]); net.run(ticks=int(sys.argv[2])); "
               "print(json.dumps(tracemalloc.get_traced_memory()))")


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def vm_rss_mb() -> float:
    """Current resident set size (VmRSS from /proc/self/status) in MB."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return float("nan")


def run_child(args: list[str]) -> tuple[float, float, str]:
    """Run a child process; returns (wall seconds from spawn to exit, peak RSS MB from
    wait4's ru_maxrss, stdout)."""
    t0 = time.monotonic()
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=ROOT,
                         env=CHILD_ENV)
    out = p.stdout.read()
    err = p.stderr.read()
    _, status, rusage = os.wait4(p.pid, 0)
    wall = time.monotonic() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise RuntimeError(f"child failed ({p.returncode}): {' '.join(args)}\n"
                           f"{err.decode(errors='replace')}")
    return wall, rusage.ru_maxrss / 1024, out.decode()


def two_thread_speedup(n: int = 1000, repeats: int = 50) -> float:
    """How much faster two threads do two independent streams of large NumPy operations
    (which release the GIL) than one thread doing both: the most threads can give."""
    import threading

    import numpy as np
    arrays = [np.full((n, n), 0.5, dtype=np.float32) for _ in range(4)]

    def work(x, y):
        for _ in range(repeats):
            np.multiply(x, 0.5, out=y)
            np.add(y, x, out=y)
    work(arrays[0], arrays[1])
    t = time.perf_counter()
    work(arrays[0], arrays[1])
    work(arrays[2], arrays[3])
    serial = time.perf_counter() - t
    threads = [threading.Thread(target=work, args=(arrays[k], arrays[k + 1])) for k in (0, 2)]
    t = time.perf_counter()
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    return serial / (time.perf_counter() - t)


# --- one benchmark -------------------------------------------------------------------------

def tick_time(step, run, quick: bool) -> tuple[float, float, int]:
    """Warm up (at least 10 ticks and 0.3 s), then 3 batches of ``run(ticks=n)`` sized so the
    three take about 1.5 s (0.4 s with ``quick``): (median us per tick, the warm-up's
    estimate in seconds per tick, ticks timed)."""
    target = 0.4 if quick else 1.5
    gc.collect()
    stamps = [time.perf_counter()]
    while len(stamps) < 11 or stamps[-1] - stamps[0] < (0.1 if quick else 0.3):
        step()
        stamps.append(time.perf_counter())
    half = len(stamps) // 2          # estimate from the second half (first ticks fault in)
    per_tick = (stamps[-1] - stamps[half]) / (len(stamps) - 1 - half)
    batch = max(3, int(target / 3 / per_tick))
    times = []
    for _ in range(3):
        t = time.perf_counter()
        run(ticks=batch)
        times.append((time.perf_counter() - t) / batch)
    return statistics.median(times) * 1e6, per_tick, 3 * batch


def numpy_loop(net):
    """The yardstick: a hand-written Python loop doing each module's work as plain NumPy
    calls on arrays of its sizes (Add: np.add, Scale: np.multiply by the factor, Integrator:
    two calls, Constant: a copy, ...; modules of other classes: a copy), without a kernel.
    Returns one tick as a function."""
    import numpy as np
    calls = []
    for inst in net.schedule:
        module = inst.module
        out = np.full(net.buffer_array(f"{inst.path}.{next(iter(module._ik_outputs))}").size,
                      0.5, np.float32)
        a, b = np.full_like(out, 0.25), np.full_like(out, 0.75)
        name = inst.entry.name
        if name in ("Add", "Subtract", "Multiply", "Max", "Min"):
            ufunc = {"Add": np.add, "Subtract": np.subtract, "Multiply": np.multiply,
                     "Max": np.maximum, "Min": np.minimum}[name]
            calls.append(functools.partial(ufunc, a, b, out=out))
        elif name == "Scale":
            calls.append(functools.partial(np.multiply, a, module.factor, out=out))
        elif name == "Tanh":
            calls.append(functools.partial(np.tanh, a, out=out))
        elif name == "Threshold":
            calls.append(functools.partial(np.greater, a, np.float32(module.threshold), out=out))
        elif name == "Integrator":
            calls.append(functools.partial(np.multiply, out, module.alpha, out=out))
            calls.append(functools.partial(np.add, out, b, out=out))
        elif name == "Sum":
            calls.append(functools.partial(np.sum, a))
        else:
            calls.append(functools.partial(np.copyto, out, a))

    def tick():
        for call in calls:
            call()
    return tick



def measure(name: str, path: str, quick: bool) -> dict:
    import ikaros

    res = {"name": name}
    # Build time: ikaros.load only (imports and class discovery already done).
    builds = []
    budget = 0.5 if quick else 2.0
    t_all = time.perf_counter()
    net = None
    while True:
        if net is not None:
            net.close()
            net = None
        gc.collect()
        t = time.perf_counter()
        net = ikaros.load(path)
        builds.append(time.perf_counter() - t)
        if len(builds) >= (3 if quick else 5) or time.perf_counter() - t_all > budget:
            break
    res["build_ms"] = statistics.median(builds) * 1e3
    res["modules"] = len(net.schedule)
    res["connections"] = len(net.runs)

    # compiled="auto" makes the compiled tick in the background: wait for it (not timed)
    res["compiled_modules"] = net.wait_compiled()
    us, per_tick, res["ticks_timed"] = tick_time(net.step, net.run, quick)
    res["us_tick"] = us
    res["us_module_tick"] = res["us_tick"] / res["modules"]
    net.close()
    del net
    # the same with the compiled tick on and off (whatever the model's default is)
    for setting in ("yes", "no"):
        gc.collect()
        other = ikaros.load(path, compiled=setting)
        res[f"us_tick_{setting}"] = tick_time(other.step, other.run, quick)[0]
        if setting == "no":
            step = numpy_loop(other)
            res["us_numpy_loop"] = tick_time(step, lambda ticks: [step() for _ in
                                                                  range(ticks)], quick)[0]
        other.close()
        del other
    gc.collect()

    # Start-up: a fresh process from spawn to the end of tick 0. The same child then runs
    # a few more ticks, so its VmHWM is the peak RSS of build + run.
    extra = max(1, min(100, int(0.3 / per_tick)))
    reps = 1 if (quick or res["build_ms"] > 500) else 3
    starts, rss = [], []
    for _ in range(reps):
        t0 = time.monotonic()
        _, _, out = run_child([sys.executable, "-c", STARTUP_CODE, path, str(extra)])
        starts.append(float(out.split()[0]) - t0)
        rss.append(float(out.split()[1]))
    res["startup_ms"] = statistics.median(starts) * 1e3
    res["rss_mb"] = max(rss)
    res["rss_ticks"] = extra + 1

    # tracemalloc peak of build + run, in its own process (tracemalloc slows everything).
    _, _, out = run_child([sys.executable, "-c", TRACED_CODE, path, str(extra)])
    res["traced_mb"] = json.loads(out.strip().splitlines()[-1])[1] / 2**20
    return res


# --- real-time jitter ----------------------------------------------------------------------

def _lag_stats(lateness: list[float]) -> dict:
    s = sorted(lateness)
    p99 = s[min(len(s) - 1, int(round(0.99 * (len(s) - 1))))]
    return {"ticks": len(s), "mean_ms": statistics.fmean(s) * 1e3, "p99_ms": p99 * 1e3,
            "max_ms": s[-1] * 1e3, "drift_ms": lateness[-1] * 1e3}


def jitter_kernel(path: str, dt: float, seconds: float) -> dict:
    """net.run(real_time=True): the kernel's own real-time loop. Each tick's start is
    recorded by wrapping the network's tick method, and compared with its deadline
    first tick start + n*dt."""
    import ikaros
    net = ikaros.load(path, tick_duration=dt)
    n = int(round(seconds / dt))
    starts = [0.0] * n
    count = [0]
    inner = net._tick                   # the method run() calls once per tick
    clock = time.perf_counter

    def timed_tick():
        starts[count[0]] = clock()
        count[0] += 1
        inner()

    net._tick = timed_tick
    gc.collect()
    t0 = clock()
    net.run(ticks=n, real_time=True)
    busy_end = clock()
    net.close()
    assert count[0] == n, (count[0], n)
    # the kernel's time base starts with its first tick
    lateness = [starts[i] - (starts[0] + i * dt) for i in range(n)]
    r = _lag_stats(lateness)
    r["elapsed_s"] = busy_end - t0
    return r


def jitter_own_loop(path: str, dt: float, seconds: float) -> dict:
    """Our own loop around net.step(): sleep until 0.5 ms before the deadline, then spin."""
    import ikaros
    net = ikaros.load(path, tick_duration=dt)
    n = int(round(seconds / dt))
    lateness = [0.0] * n
    clock, sleep, step = time.perf_counter, time.sleep, net.step
    gc.collect()
    t0 = clock()
    for i in range(n):
        deadline = t0 + i * dt
        wait = deadline - clock()
        if wait > 0.0005:
            sleep(wait - 0.0005)
        while clock() < deadline:
            pass
        lateness[i] = clock() - deadline
        step()
    elapsed = clock() - t0
    net.close()
    r = _lag_stats(lateness)
    r["elapsed_s"] = elapsed
    return r


# --- soak ----------------------------------------------------------------------------------

def soak_worker(path: str, ticks: int) -> None:
    """Runs in its own process; prints one JSON line."""
    import numpy as np
    import ikaros
    rss0 = vm_rss_mb()
    net = ikaros.load(path)
    rss_loaded = vm_rss_mb()
    warm = min(1000, ticks)
    net.run(ticks=warm)
    rss_warm = vm_rss_mb()
    samples = []
    chunk = max(1, (ticks - warm) // 10)
    t = time.perf_counter()
    done = warm
    while done < ticks:
        k = min(chunk, ticks - done)
        net.run(ticks=k)
        done += k
        samples.append(vm_rss_mb())
    elapsed = time.perf_counter() - t
    finite = all(bool(np.isfinite(net.buffer_array(p + ".OUTPUT")).all()) for p in net.modules)
    rss_end = vm_rss_mb()
    net.close()
    print(json.dumps({"ticks": net.tick, "rss_imports": rss0, "rss_loaded": rss_loaded,
                      "rss_warm": rss_warm, "rss_end": rss_end,
                      "rss_max": max(samples + [rss_warm]), "elapsed_s": elapsed,
                      "timed_ticks": ticks - warm, "finite": finite}), flush=True)


# --- main ----------------------------------------------------------------------------------

def selected(name: str, patterns: list[str] | None) -> bool:
    if not patterns:
        return True
    return any(fnmatch.fnmatchcase(name, p) or name.startswith(p + "_") for p in patterns)


def machine() -> str:
    import numpy
    cpu = platform.processor() or "?"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return (f"Python {platform.python_version()}, NumPy {numpy.__version__}, {cpu}, "
            f"{os.cpu_count()} CPUs, {platform.system()} {platform.release()}")


def fmt_table(rows: list[list[str]], header: list[str]) -> str:
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(len(header))]
    line = "  ".join(h.rjust(w) if i else h.ljust(w) for i, (h, w) in
                     enumerate(zip(header, widths)))
    out = [line, "-" * len(line)]
    for r in rows:
        out.append("  ".join(str(c).rjust(w) if i else str(c).ljust(w) for i, (c, w) in
                             enumerate(zip(r, widths))))
    return "\n".join(out)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="short run (about 1-2 minutes)")
    ap.add_argument("--only", action="append", metavar="NAME",
                    help="run only this benchmark (repeatable; patterns allowed)")
    ap.add_argument("--models", metavar="DIR",
                    help="write the model files here and keep them (default: a temp dir)")
    ap.add_argument("--soak-ticks", type=int, help="ticks of the soak (default 1000000, "
                                                   "100000 with --quick)")
    ap.add_argument("--_soak", nargs=2, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)

    if args._soak:
        soak_worker(args._soak[0], int(args._soak[1]))
        return 0

    t_start = time.perf_counter()
    folder = args.models or tempfile.mkdtemp(prefix="ikaros-bench-")
    paths = models.write_all(folder)
    names = [n for n in paths if selected(n, args.only)]
    do_jitter = selected("jitter", args.only)
    do_soak = selected("soak", args.only)

    print(f"ikaros for Python benchmarks{' (--quick)' if args.quick else ''}")
    print(machine())
    _, _, out = run_child([sys.executable, "-c", "import ikaros; " + PEAK_CODE])
    base_rss = float(out.split()[0])
    print(f"Baseline: a process that only imports ikaros peaks at {base_rss:.1f} MB RSS.")
    print(flush=True)

    import ikaros
    ikaros.load(paths["chain_10_d1"]).close()     # imports and class discovery, not timed
    compiled = ikaros.load(paths["chain_100_d0"], compiled="yes")   # numba's start-up too
    if not compiled.compiled_modules:
        print("The compiled tick is not available (numba is not installed: pip install "
              "'ikaros[fast]'): its columns show the NumPy kernel.")
    compiled.close()

    results = []
    for name in names:
        log(f"... {name}")
        r = measure(name, paths[name], args.quick)
        log(f"    build {r['build_ms']:.1f} ms, {r['us_tick']:.1f} us/tick, "
            f"start-up {r['startup_ms']:.0f} ms")
        results.append(r)

    robot_us = next((r["us_tick"] for r in results if r["name"] == "robot_320"), None)
    if results:
        header = ["benchmark", "modules", "conns", "compiled", "build ms", "start-up ms",
                  "us/tick", "us/module-tick", "compiled us/tick", "NumPy us/tick",
                  "NumPy loop us/tick", "ticks timed", "peak RSS MB", "traced MB"]
        rows = [[r["name"], r["modules"], r["connections"], r["compiled_modules"],
                 f"{r['build_ms']:.1f}", f"{r['startup_ms']:.0f}", f"{r['us_tick']:.1f}",
                 f"{r['us_module_tick']:.3f}", f"{r['us_tick_yes']:.1f}",
                 f"{r['us_tick_no']:.1f}", f"{r['us_numpy_loop']:.1f}", r["ticks_timed"],
                 f"{r['rss_mb']:.1f}", f"{r['traced_mb']:.1f}"] for r in results]
        print(fmt_table(rows, header))
        print("build ms: ikaros.load() in this process, median of up to 5 builds. start-up "
              "ms: new process from spawn to the end of tick 0.\nus/tick: median of 3 timed "
              "batches after warm-up, as the model loads by default (compiled: the modules "
              "in the compiled tick); us/module-tick = us/tick / modules.\ncompiled / NumPy "
              "us/tick: the same with compiled=\"yes\" / \"no\". NumPy loop: the "
              "yardstick, a hand-written Python loop of each module's NumPy calls on arrays "
              "of its sizes, no kernel.\npeak RSS MB: "
              "VmHWM of the start-up process (build + tick 0 + up to 100 more ticks), "
              f"including the {base_rss:.0f} MB import baseline.\ntraced MB: tracemalloc peak "
              "of build + the same ticks, in a separate process, counting only allocations "
              "made after import.")
        print(flush=True)

    if any(r["name"].startswith("pipelines_") for r in results):
        print(f"Two-core check: plain NumPy on 1000x1000 float32 arrays, two threads vs one "
              f"after the other: {two_thread_speedup():.2f}x faster. pipelines_t2 can gain "
              f"at most this much over pipelines_t1; on this virtual machine the figure "
              f"drops near 1 when the host gives the second core to someone else.")
        print(flush=True)

    robot = paths["robot_320"]
    if do_jitter:
        seconds = 2.0 if args.quick else 10.0
        rows = []
        for hz in (1000, 100):
            dt = 1.0 / hz
            for label, fn in (("run(real_time=True)", jitter_kernel),
                              ("own loop: sleep+spin, step()", jitter_own_loop)):
                log(f"... jitter {hz} Hz {label}, {seconds:g} s")
                j = fn(robot, dt, seconds)
                rows.append([f"robot_320 @ {hz} Hz", label, j["ticks"], f"{j['mean_ms']:.3f}",
                             f"{j['p99_ms']:.3f}", f"{j['max_ms']:.3f}",
                             f"{j['drift_ms']:.3f}", f"{j['elapsed_s']:.2f}"])
        print(f"Real-time jitter, robot_320, {seconds:g} s per row (lag = tick start minus "
              "its deadline start + n*dt)")
        print(fmt_table(rows, ["model", "loop", "ticks", "lag mean ms", "lag p99 ms",
                               "lag max ms", "drift ms", "elapsed s"]))
        print(flush=True)

    if do_soak:
        ticks = args.soak_ticks or (100_000 if args.quick else 1_000_000)
        if robot_us is None:
            net = ikaros.load(robot)
            net.run(ticks=200)
            t = time.perf_counter()
            net.run(ticks=2000)
            robot_us = (time.perf_counter() - t) / 2000 * 1e6
            net.close()
        estimate = ticks * robot_us * 1e-6
        print(f"Soak estimate: {ticks:,} ticks of robot_320 at {robot_us:.0f} us/tick "
              f"= {estimate:.0f} s ({estimate / 60:.1f} min)"
              + ("; over 5 minutes, running it anyway" if estimate > 300 else ""), flush=True)
        log(f"... soak {ticks:,} ticks (about {estimate:.0f} s)")
        _, _, out = run_child([sys.executable, os.path.abspath(__file__), "--_soak", robot,
                               str(ticks)])
        s = json.loads(out.strip().splitlines()[-1])
        print(f"Soak robot_320: {s['ticks']:,} ticks in {s['elapsed_s']:.1f} s "
              f"({s['elapsed_s'] / max(1, s['timed_ticks']) * 1e6:.1f} us/tick); VmRSS "
              f"start {s['rss_loaded']:.1f} MB (after load; {s['rss_imports']:.1f} MB after "
              f"imports), after 1000 ticks {s['rss_warm']:.1f} MB, end {s['rss_end']:.1f} MB "
              f"(end - start {s['rss_end'] - s['rss_loaded']:+.1f} MB, max sampled "
              f"{s['rss_max']:.1f} MB); outputs finite at the end: "
              f"{'yes' if s['finite'] else 'NO'}")
        print(flush=True)

    print(f"Total benchmark time: {time.perf_counter() - t_start:.0f} s")
    if not args.models:
        shutil.rmtree(folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
