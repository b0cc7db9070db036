"""Damaged recordings: a recording cut at 5 % steps, and overwritten with 256 bytes (zeros,
then noise) at every 256-byte-aligned offset, each opened with ``open_recording``. Prints,
per kind of damage, how many were refused, read whole and unchanged (the damage fell where
nothing is read), read in part (said so), and read with a value that is not what was
recorded (there must be none), and the most CPU time one open took.

    python benchmarks/recording_damage.py                    # a 20000-tick recording
    python benchmarks/recording_damage.py --file old.h5      # a recording made before

Each open runs in this process; a hang would stop the benchmark (a timer then prints
where, and exits).
"""
from __future__ import annotations

import argparse
import faulthandler
import os
import sys
import tempfile
import time
import warnings

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from ikaros.experiments import open_recording  # noqa: E402
from ikaros.testing import load_body  # noqa: E402

BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Sweep" name="Grid" outputsize_x="8" outputsize_y="4" min="0" max="100000000"
        step="0.5"/>
"""
ATTRIBUTES = ("model", "parameters", "command_line", "model_file")


def record(folder: str, ticks: int) -> str:
    net = load_body(folder, BODY)
    path = os.path.join(folder, "run.h5")
    with net.record(path):
        net.run(ticks=ticks)
    net.close()
    return path


def outcome(path: str, whole) -> str:
    """refused, whole, partial or WRONG (a value not as recorded)."""
    try:
        ds = open_recording(path)
    except (OSError, ValueError) as e:
        assert "\n" not in str(e) and path in str(e), str(e)
        return "refused"
    n = ds.sizes["tick"]
    for name in list(ds.data_vars) + ["tick", "time", "real_time"]:
        if not np.array_equal(ds[name].values, whole[name].values[:n]):
            return "WRONG"
    if any(ds.attrs[key] != whole.attrs[key] for key in ATTRIBUTES):
        return "WRONG"
    if n < whole.sizes["tick"]:
        return "partial" if ds.attrs.get("damage") else "WRONG"
    return "whole"


def sweep(source: str, damages, scratch: str) -> tuple[dict, float]:
    whole = open_recording(source)
    data = open(source, "rb").read()
    counts: dict = {}
    most = 0.0
    for name, damage in damages(data):
        path = os.path.join(scratch, "damaged.h5")
        with open(path, "wb") as f:
            f.write(damage)
        faulthandler.dump_traceback_later(60, exit=True)     # a hang: say where, and end
        cpu = time.process_time()
        kind = outcome(path, whole)
        most = max(most, time.process_time() - cpu)
        faulthandler.cancel_dump_traceback_later()
        counts[kind] = counts.get(kind, 0) + 1
        if kind == "WRONG":
            print(f"  a wrong value: {name}")
    return counts, most


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--file", help="a recording to damage (default: one recorded here)")
    p.add_argument("--ticks", type=int, default=20000)
    opts = p.parse_args()
    warnings.simplefilter("ignore")
    with tempfile.TemporaryDirectory() as scratch:
        source = opts.file or record(scratch, opts.ticks)
        size = os.path.getsize(source)
        rng = np.random.default_rng(1)
        kinds = {
            "cut at 5 % steps and at 100 B to 16 KiB": lambda data: [
                (f"cut at {n}", data[:n]) for n in
                [100, 1024, 2048, 4096, 8192, 16384] + [size * k // 20 for k in range(1, 20)]],
            "256 zero bytes at every 256th byte": lambda data: [
                (f"zeros at {at}", data[:at] + bytes(256) + data[at + 256:])
                for at in range(0, size - 256, 256)],
            "256 bytes of noise at every 256th byte": lambda data: [
                (f"noise at {at}", data[:at] + rng.integers(0, 256, 256, np.uint8).tobytes()
                 + data[at + 256:]) for at in range(0, size - 256, 256)],
        }
        print(f"{source}: {size} bytes")
        for title, damages in kinds.items():
            counts, most = sweep(source, damages, scratch)
            print(f"{title}: {counts}; the longest open took {most * 1000:.0f} ms of CPU")


if __name__ == "__main__":
    main()
