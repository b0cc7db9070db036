"""Parameter sweeps: every combination of a grid of settings as a separate run, in local
processes or on Ray, with a results table (pandas) and one recording per run."""
from __future__ import annotations

import importlib.util
import itertools
import logging
import math
import os
import sys
import threading
import time
import traceback
from dataclasses import dataclass, field

import numpy as np

from . import poolworkers
from .resume import done_before, signature, write_signature
from .recording import Recorder
from .signals import select_outputs
from .sweepprogress import INTERRUPTED, Reporter, TickCounters, run_in_steps

MAX_METRIC_ELEMENTS = 16       # a recorded output this small has its final values in the table
CUT_OFF_SECONDS = 1.0          # for the runs cut off by Ctrl-C to send their rows


# --- the grid -----------------------------------------------------------------------------
def parse_values(text: str) -> list:
    """The values of one ``--set NAME=VALUES``: ``start:stop:step`` (stop included),
    ``start:stop`` (whole numbers, step 1), ``a,b,c``, or one value."""
    text = text.strip()
    if ":" in text:
        parts = text.split(":")
        if len(parts) not in (2, 3) or not all(p.strip() for p in parts):
            raise ValueError(f'"{text}" is not start:stop or start:stop:step')
        try:
            numbers = [float(p) for p in parts]
        except ValueError:
            raise ValueError(f'"{text}": start, stop and step must be numbers') from None
        start, stop = numbers[0], numbers[1]
        step = numbers[2] if len(parts) == 3 else 1.0
        if step == 0 or not all(math.isfinite(x) for x in numbers) or \
                (stop - start) / step < 0:
            raise ValueError(f'"{text}": the step must lead from start to stop')
        count = int(math.floor((stop - start) / step + 1e-9)) + 1
        whole = all(float(p).is_integer() and "." not in p and "e" not in p.lower()
                    for p in parts)
        if whole:
            return [int(start + k * step) for k in range(count)]
        return [float(f"{start + k * step:.12g}") for k in range(count)]
    items = [v.strip() for v in text.split(",")]
    if not all(items):
        raise ValueError(f'"{text}" has an empty value')
    return [_number(v) for v in items]


def _number(text: str):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def grid(settings: dict[str, list]) -> list[dict]:
    """Every combination of the settings' values, the last setting varying fastest."""
    names = list(settings)
    return [dict(zip(names, values))
            for values in itertools.product(*(settings[n] for n in names))]


# --- one run ------------------------------------------------------------------------------
@dataclass
class RunSpec:
    """One run of a sweep: what a worker needs (the model's text travels with it)."""
    index: int
    model: str
    model_text: str
    settings: dict
    ticks: int
    record: list = field(default_factory=list)
    recording: str | None = None        # the HDF5 file of this run, when recordings are kept
    every: int = 1


def run_one(spec: RunSpec, report=None) -> dict:
    """Build and run one combination (telling ``report`` the ticks done as it goes, when
    given); never raises: a failure is the row's status and
    error (with the traceback's last line for where), a Ctrl-C or SIGTERM the status
    "interrupted" with the ticks run (its recording is left not finished)."""
    started = time.perf_counter()
    row = {"run": spec.index, **spec.settings}
    net = None
    try:
        net = _build(spec)
        metrics = _run(net, spec, report)
        row.update(status="ok", error="", ticks=net.tick)
        row.update(metrics)
    except BaseException as e:          # noqa: BLE001: a run's failure is data, not a crash
        row.update(status=INTERRUPTED if isinstance(e, KeyboardInterrupt) else "error",
                   error="" if isinstance(e, KeyboardInterrupt) else _error_text(e),
                   ticks=net.tick if net is not None else 0)
    finally:
        if net is not None:
            try:
                net.close()
            except Exception as e:      # noqa: BLE001
                if row.get("status") == "ok":
                    row.update(status="error", error=_error_text(e))
    row["seconds"] = time.perf_counter() - started
    row["recording"] = spec.recording or ""
    return row


def _error_text(e: BaseException) -> str:
    where = traceback.extract_tb(e.__traceback__)
    place = f" (at {os.path.basename(where[-1].filename)}:{where[-1].lineno})" if where else ""
    return f"{type(e).__name__}: {e}{place}"


def _build(spec: RunSpec):
    from ..kernel.builder import Builder
    from ..language.diagnostics import Diagnostics
    from ..language.reader import read_file
    from ..language.values import value_text
    overrides = {k: v for k, v in spec.settings.items() if "." not in k}
    tree = read_file(spec.model, spec.model_text, root_tag="group")
    later = {}
    for path, value in spec.settings.items():
        if "." in path and not _set_in_tree(tree, path, value_text(value)
                                            if not isinstance(value, str) else value):
            later[path] = value
    net = Builder(spec.model, overrides, model=tree,
                  diagnostics=Diagnostics(quiet=True)).build()
    net.log_level = -1          # the runs print nothing; failures go to the table
    for path in spec.settings.keys() - later.keys():
        if "." in path:
            net.parameter(path)       # a name the module does not have is an error
    for path, value in later.items():     # modules the tree does not show (class files)
        net.set_parameter(path, value)
    return net


def _set_in_tree(tree, path: str, value: str) -> bool:
    """Set a module's parameter in the model tree before the build, so that init sees it.
    False when the module is not written in the file itself."""
    *names, parameter = path.split(".")
    node = tree
    for name in names:
        node = next((n for n in node.elements() if n.tag in ("group", "module") and
                     (n.get("name") or n.get("class")) == name), None)
        if node is None:
            return False
    if node.tag != "module":
        return False
    node.attrs[parameter] = value
    return True


def _run(net, spec: RunSpec, report=None) -> dict:
    """Run (recording when asked); the final values of the recorded outputs."""
    if not spec.record:
        _ticks(net, spec, report)
        return {}
    signals, index = select_outputs(net, spec.record)
    if spec.recording:
        with Recorder(net, spec.recording, only=spec.record, every=spec.every):
            _ticks(net, spec, report)
    else:
        _ticks(net, spec, report)
    return final_metrics(signals, net.arena.block[index])


def _ticks(net, spec: RunSpec, report) -> None:
    """The run's ticks; after them (in a worker) a SIGTERM lets the run close."""
    try:
        run_in_steps(net, spec.ticks, report)
    finally:
        poolworkers.closing()


def _shortest(value) -> float:
    """A float32 as the float its shortest text gives (0.8, not 0.800000011920929)."""
    return float(str(np.float32(value)))


def final_metrics(signals, final) -> dict:
    """{column: value} of the final values of small recorded outputs: ``A.OUTPUT`` for
    one element, ``A.OUTPUT[i]`` (flat index) for up to 16."""
    metrics = {}
    for s in signals:
        values = final[s.start:s.stop]
        if values.size == 1:
            metrics[s.name] = _shortest(values[0])
        elif values.size <= MAX_METRIC_ELEMENTS:
            for i, v in enumerate(values):
                metrics[f"{s.name}[{i}]"] = _shortest(v)
    return metrics


# --- many runs ----------------------------------------------------------------------------
def sweep(model: str, settings: dict[str, list | str], ticks: int,
          record: list[str] | str | None = None, out: str | None = None, every: int = 1,
          workers: int | None = None, address: str | None = None, backend: str = "auto",
          retries: int = 1, table_format: str = "parquet", progress: bool | None = None,
          on_failure=None):
    """Run ``model`` once for every combination of ``settings`` (name: list of values or a
    ``--set`` text such as ``"0.05:0.5:0.05"``) for ``ticks`` ticks, and return the results
    table as a pandas DataFrame: one row per run with its settings, ``status`` ("ok" or
    "error"), ``error``, ``ticks``, ``seconds``, ``attempts``, the final values of the
    recorded outputs, and ``recording`` (its HDF5 file under ``out``).

    A name with a dot sets a module parameter (``Q.alpha``), before the build; one without
    sets a top-group attribute (``seed``). ``backend``: "local" (``workers`` processes, the
    machine's cores by default), "ray" (a local Ray instance, or the cluster at
    ``address``), or "auto" (Ray when an address is given, or when Ray is installed and no
    ``workers`` are; local processes otherwise). A failed run is tried ``retries`` more
    times, then reported (``on_failure(row)``, and in the table); it never stops the
    others. With ``out`` the table is also written there (results.parquet or results.csv).

    Ctrl-C or SIGTERM ends the sweep within seconds: its worker processes end their runs
    (the recordings are left not finished), the table of the runs so far is written (the
    others "interrupted", with the ticks they ran) and KeyboardInterrupt is raised. The
    workers end with the sweep however it ends (also SIGKILL). A sweep into an ``out``
    that holds one with the same model, grid, ticks and recording (resume.py) runs only
    the runs that one did not finish.
    """
    import pandas as pd
    values = {name: parse_values(v) if isinstance(v, str) else list(v)
              for name, v in settings.items()}
    combos = grid(values)
    patterns = [record] if isinstance(record, str) else list(record or [])
    model = os.path.abspath(model)
    with open(model, encoding="utf-8") as f:
        text = f.read()
    if out:
        os.makedirs(out, exist_ok=True)
    width = len(str(len(combos)))
    specs = [RunSpec(k, model, text, combo, int(ticks), patterns,
                     os.path.abspath(os.path.join(out, f"run_{k:0{width}d}.h5"))
                     if out and patterns else None, int(every))
             for k, combo in enumerate(combos)]
    if patterns and specs:
        _check_patterns(specs[0])
    kind = _backend(backend, workers, address)
    runner = ray_runner(address, workers) if kind == "ray" else local_runner(workers)
    before = {}
    if out:
        sign = signature(text, values, ticks, patterns, every)
        before = done_before(out, table_format, sign, specs)
        write_signature(out, sign)
        if before and progress is not False:
            print(f"ikaros sweep: {len(before)} of {len(specs)} runs were done before in "
                  f"{out}; running the others", file=sys.stderr, flush=True)
    reporter = Reporter(len(specs) - len(before), progress, on_failure,
                        TickCounters(len(specs)) if kind == "local" else None)
    try:
        runner([s for s in specs if s.index not in before], retries, reporter)
    except KeyboardInterrupt:
        if out:
            rows = {**before, **{r["run"]: r for r in reporter.rows}}
            rows.update({s.index: _interrupted_row(s) for s in specs if s.index not in rows})
            write_table(_table(pd, rows.values(), values), out, table_format)
        raise
    table = _table(pd, list(before.values()) + reporter.rows, values)
    if out:
        write_table(table, out, table_format)
    return table


def _table(pd, rows, values: dict):
    """The results table: one row per run in order, the settings and status first."""
    table = pd.DataFrame(sorted(rows, key=lambda r: r["run"]))
    first = ["run", *values, "status", "error", "attempts", "ticks", "seconds", "recording"]
    return table[first + [c for c in table.columns if c not in first]]


def _interrupted_row(spec: RunSpec) -> dict:
    """The row of a run that was not run (or whose end never came back)."""
    return {"run": spec.index, **spec.settings, "status": INTERRUPTED, "error": "",
            "attempts": 0, "ticks": 0, "seconds": 0.0, "recording": spec.recording or ""}


def _check_patterns(spec: RunSpec) -> None:
    """A --record pattern that matches no output is an error before any run starts (a
    model that does not build is left to the runs to report)."""
    try:
        net = _build(spec)
    except Exception:       # noqa: BLE001: reported by the runs themselves
        return
    try:
        select_outputs(net, spec.record)
    finally:
        net.close()


def write_table(table, out: str, table_format: str) -> str:
    path = os.path.join(out, f"results.{table_format}")
    if table_format == "csv":
        table.to_csv(path, index=False)
    elif table_format == "parquet":
        table.to_parquet(path, index=False)
    else:
        raise ValueError(f'unknown table format "{table_format}" (parquet or csv)')
    return path


def _backend(backend: str, workers, address) -> str:
    if backend not in ("auto", "local", "ray"):
        raise ValueError(f'unknown backend "{backend}" (auto, local or ray)')
    if backend != "auto":
        return backend
    if address:
        return "ray"
    if workers is None and importlib.util.find_spec("ray") is not None:
        return "ray"
    return "local"


def local_runner(workers: int | None):
    """Runs the specs in ``workers`` local processes (in this process when 1). A worker
    process that dies (killed, out of memory) fails only the run that was in it (each run
    of the broken pool is run again alone to find it), which is tried again while it has
    retries left."""
    def run(specs: list[RunSpec], retries: int, reporter: Reporter) -> list[dict]:
        count = workers or os.cpu_count() or 1
        try:
            if count == 1:
                for spec in specs:
                    reporter.started(spec)
                    report = reporter.counters.reporter(spec.index) \
                        if reporter.counters is not None else None
                    row = _with_retries(lambda s=spec: run_one(s, report), retries)
                    reporter.done(row)
                    if row["status"] == INTERRUPTED:
                        raise KeyboardInterrupt
                return reporter.rows
            return _in_processes(specs, min(count, len(specs) or 1), retries, reporter)
        finally:
            reporter.close()
    return run


def _in_processes(specs, count: int, retries: int, reporter) -> list[dict]:
    import concurrent.futures as cf
    import multiprocessing
    # fork: the runs need nothing of this process but the specs, and a script or notebook
    # that calls sweep() needs no "if __name__ == '__main__'" guard
    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    queue = [(spec, 1) for spec in specs]
    queue.reverse()                     # popped from the end: in order
    rows = []

    def finish(spec, attempt, row):
        if row["status"] != "ok" and attempt <= retries:
            queue.append((spec, attempt + 1))
            return
        row["attempts"] = attempt
        rows.append(row)
        reporter.done(row)
    while queue:
        suspects: list = []       # runs that were in the pool when one of its processes died
        pool = _pool(count, context, reporter.counters)
        running: dict = {}
        try:
            while (queue and not suspects) or running:
                while queue and len(running) < count and not suspects:
                    spec, attempt = queue.pop()
                    reporter.started(spec)
                    running[pool.submit(poolworkers.run, run_one, spec)] = (spec, attempt)
                done, _ = cf.wait(running, return_when=cf.FIRST_COMPLETED)
                for future in done:
                    spec, attempt = running.pop(future)
                    try:
                        row = future.result()
                    except cf.process.BrokenProcessPool:
                        suspects.append((spec, attempt))
                        continue
                    finish(spec, attempt, row)
        except KeyboardInterrupt:
            _end_workers(pool, running, reporter)
            raise
        pool.shutdown(wait=True)
        # A broken pool fails every run it held; run each again alone to learn which one
        # took its process down (only that one is charged).
        for spec, attempt in suspects:
            finish(spec, attempt, _alone(spec, context, reporter))
    return rows


def _pool(count: int, context, counters: TickCounters):
    """A process pool whose workers end with this process (poolworkers.py) and write the
    ticks their runs have done into ``counters``."""
    import concurrent.futures as cf
    return cf.ProcessPoolExecutor(max_workers=count, mp_context=context,
                                  initializer=poolworkers.start,
                                  initargs=(os.getpid(), counters))


def _end_workers(pool, running: dict, reporter) -> None:
    """On Ctrl-C or SIGTERM: SIGTERM to every worker, and the rows of the runs they cut off
    (those that come back within CUT_OFF_SECONDS) to the reporter. A worker is never
    killed while it may still be closing its run's recording (a file closed half way stays
    marked open for writing): each ends by itself (poolworkers.py), and one still there
    when its grace is over is stuck, and killed."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    for process in processes:
        process.terminate()
    deadline = time.monotonic() + CUT_OFF_SECONDS
    for future, (spec, attempt) in running.items():
        try:
            row = future.result(timeout=max(deadline - time.monotonic(), 0))
        except BaseException:       # noqa: BLE001: not back in time, or its process died
            continue
        row["attempts"] = attempt
        reporter.done(row)
    pool.shutdown(wait=False, cancel_futures=True)
    threading.Thread(target=_kill_stuck, args=(processes, poolworkers.CLOSE_GRACE + 1.0),
                     name="ikaros-sweep-end", daemon=True).start()


def _kill_stuck(processes: list, seconds: float) -> None:
    """Kill the processes still there ``seconds`` from now."""
    deadline = time.monotonic() + seconds
    for process in processes:
        process.join(max(deadline - time.monotonic(), 0))
        if process.is_alive():
            process.kill()


def _alone(spec: RunSpec, context, reporter) -> dict:
    """Run one spec in a process of its own; a process that dies fails the run."""
    import concurrent.futures as cf
    pool = _pool(1, context, reporter.counters)
    reporter.started(spec)
    future = pool.submit(poolworkers.run, run_one, spec)
    try:
        return future.result()
    except cf.process.BrokenProcessPool:
        return _error_row(spec, "a worker process died while this run was in it")
    except KeyboardInterrupt:
        _end_workers(pool, {future: (spec, 1)}, reporter)
        raise
    finally:
        pool.shutdown(wait=False)


def _error_row(spec: RunSpec, error: str) -> dict:
    return {"run": spec.index, **spec.settings, "status": "error", "error": error,
            "ticks": 0, "seconds": 0.0, "recording": spec.recording or ""}


def _with_retries(attempt, retries: int) -> dict:
    for k in range(retries + 1):
        row = attempt()
        row["attempts"] = k + 1
        if row["status"] in ("ok", INTERRUPTED):
            break
    return row


def ray_runner(address: str | None, workers: int | None):
    """Runs the specs as Ray tasks: on a local Ray instance (``workers`` CPUs, the machine's
    by default), or on the cluster at ``address`` ("auto" finds a running one)."""
    def run(specs: list[RunSpec], retries: int, reporter: Reporter) -> list[dict]:
        try:
            import ray
        except ImportError:
            raise ImportError("sweeps on Ray need ray: pip install 'ikaros[cluster]' (or "
                              "use --workers N for local processes)") from None
        started_here = not ray.is_initialized()
        if started_here:
            if address:         # the cluster's nodes have ikaros installed
                ray.init(address=address, log_to_driver=False, logging_level=logging.ERROR)
            else:               # local workers import ikaros from where this one did
                package_root = os.path.dirname(os.path.dirname(os.path.dirname(
                    os.path.abspath(__file__))))
                env = {"PYTHONPATH": os.pathsep.join(
                    p for p in (package_root, os.environ.get("PYTHONPATH")) if p)}
                ray.init(num_cpus=workers or os.cpu_count(), include_dashboard=False,
                         runtime_env={"env_vars": env}, log_to_driver=False,
                         logging_level=logging.ERROR)
        remote = ray.remote(num_cpus=1, max_retries=0)(run_one)
        rows = []
        try:
            pending = {remote.remote(s): (s, 1) for s in specs}
            while pending:
                done, _ = ray.wait(list(pending), num_returns=1)
                for ref in done:
                    spec, attempt = pending.pop(ref)
                    try:
                        row = ray.get(ref)
                    except Exception as e:      # noqa: BLE001: a lost node or worker
                        row = _error_row(spec, f"the Ray task failed: {type(e).__name__}: "
                                               f"{e}")
                    if row["status"] != "ok" and attempt <= retries:
                        pending[remote.remote(spec)] = (spec, attempt + 1)
                        continue
                    row["attempts"] = attempt
                    rows.append(row)
                    reporter.done(row)
            return rows
        finally:
            reporter.close()
            if started_here:
                ray.shutdown()
    return run
