"""``ikaros sweep``: run a model for every combination of a grid of settings."""
from __future__ import annotations

import argparse
import os
import sys
import time

from ..errors import ModelError

EXIT_OK, EXIT_ERROR, EXIT_USAGE = 0, 1, 2



def _whole(minimum: int):
    def parse(text: str) -> int:
        if not text.lstrip("+").isdigit() or int(text) < minimum:
            raise argparse.ArgumentTypeError(f'"{text}" is not a whole number >= {minimum}')
        return int(text)
    return parse


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="ikaros sweep",
                description="Run a model once for every combination of the --set values, "
                            "in parallel (local processes, or Ray), and collect a results "
                            "table.",
                epilog="VALUES: start:stop:step (stop included), start:stop (whole numbers), "
                       "a,b,c or one value. NAME with a dot sets a module parameter before "
                       "the build (Q.alpha); without, a top-group attribute (seed). Exit "
                       "status: 0 every run ok, 1 a run failed (the others still ran), "
                       "2 bad usage.")
    p.add_argument("model", metavar="MODEL.ikg")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUES",
                   dest="settings", help="a setting to vary (repeatable)")
    p.add_argument("--ticks", type=_whole(1), required=True, metavar="N",
                   help="ticks per run")
    p.add_argument("--record", action="append", metavar="PATTERN",
                   help="outputs to record (glob patterns of addresses, repeatable); their "
                        "final values go into the table, and with --out each run's "
                        "recording into DIR/run_K.h5")
    p.add_argument("--record-every", type=_whole(1), default=1, metavar="K",
                   help="record every K-th tick")
    p.add_argument("--out", metavar="DIR",
                   help="write the results table and the recordings into DIR; without it "
                        "the table is printed as CSV")
    p.add_argument("--format", choices=("parquet", "csv"), default="parquet",
                   help="the results table's format in DIR (default parquet)")
    p.add_argument("--workers", type=_whole(1), metavar="N",
                   help="run in N local processes (without --address and without Ray "
                        "installed: the machine's cores)")
    p.add_argument("--address", metavar="ADDRESS",
                   help="run on the Ray cluster at ADDRESS (auto: the one running here); "
                        "without it and without --workers a local Ray instance is used "
                        "when Ray is installed")
    p.add_argument("--retries", type=_whole(0), default=1, metavar="N",
                   help="try a failed run N more times (default 1)")
    p.add_argument("-q", "--quiet", action="store_true",
                   help="no progress bar and no summary; failures are still reported")
    return p


def main(argv: list[str]) -> int:
    from .sweeps import parse_values, sweep
    p = parser()
    opts = p.parse_args(argv)
    settings = {}
    for item in opts.settings:
        name, eq, values = item.partition("=")
        if not eq or not name:
            p.error(f'--set "{item}" is not NAME=VALUES')
        try:
            settings[name] = parse_values(values)
        except ValueError as e:
            p.error(f"--set {name}: {e}")
    if not os.path.isfile(opts.model):
        print(f'ikaros sweep: error: no model file "{opts.model}"', file=sys.stderr)
        return EXIT_ERROR
    if opts.address and opts.workers:
        p.error("--address and --workers can not be used together")
    started = time.perf_counter()
    try:
        table = sweep(opts.model, settings, opts.ticks, record=opts.record, out=opts.out,
                      every=opts.record_every, workers=opts.workers, address=opts.address,
                      retries=opts.retries, table_format=opts.format,
                      progress=False if opts.quiet else None)
    except (ImportError, OSError, ValueError, ModelError) as e:
        print(f"ikaros sweep: error: {e}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        where = f"; the table of the runs so far is in " \
                f"{os.path.join(opts.out, 'results.' + opts.format)}" if opts.out else ""
        print(f"ikaros sweep: interrupted{where}", file=sys.stderr)
        return EXIT_ERROR
    failed = int((table["status"] != "ok").sum())
    if opts.out is None:
        table.to_csv(sys.stdout, index=False)
    if not opts.quiet:
        where = f"; table in {os.path.join(opts.out, 'results.' + opts.format)}" \
            if opts.out else ""
        print(f"ikaros sweep: {len(table)} runs, {len(table) - failed} ok, {failed} failed, "
              f"in {time.perf_counter() - started:.1f} s{where}", file=sys.stderr)
    return EXIT_ERROR if failed else EXIT_OK
