"""What a recording killed with SIGKILL loses: the seconds between the kill and the last
tick the file holds, for each flush interval.

    python benchmarks/recording_loss.py                        # 5 kills at 1 s
    python benchmarks/recording_loss.py --kills 5 --flush 1 --flush 0.1

Each trial runs ``ikaros -b`` on a model whose one module outputs the wall-clock time (the
seconds modulo 1000, as float32: to about 0.1 ms), recording it with ``--record-flush``,
kills the process with SIGKILL 2 to 4 s (at random) after its recording became readable,
and reads the recording: the loss is the time of the kill minus the time the last row
holds.
"""
from __future__ import annotations

import argparse
import os
import random
import signal
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from ikaros.experiments import open_recording  # noqa: E402

WALL_CLOCK = '''import time
from ikaros import Module, Output


class WallClock(Module):
    """The wall-clock time in seconds modulo 1000."""
    OUTPUT = Output(size=1)

    def tick(self):
        self.OUTPUT[0] = time.time() % 1000
'''
MODEL = '<group name="Loss"><module class="WallClock" name="Clock"/></group>\n'


def rows(path: str) -> int:
    try:
        return open_recording(path).sizes["tick"]
    except (OSError, KeyError):
        return 0


def one_kill(folder: str, flush: float) -> float:
    """Seconds lost by one recording killed with SIGKILL."""
    out = os.path.join(folder, "run.h5")
    if os.path.exists(out):
        os.remove(out)
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    run = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-q", "-s", "1000000000",
                            os.path.join(folder, "loss.ikg"), "--record", out,
                            "--record-flush", str(flush)], env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while rows(out) == 0:
        if time.monotonic() > deadline:
            run.kill()
            raise RuntimeError("the recording did not become readable in 120 s")
        time.sleep(0.1)
    time.sleep(random.uniform(2, 4))
    killed = time.time() % 1000
    run.send_signal(signal.SIGKILL)
    run.wait()
    last = float(open_recording(out)["Clock.OUTPUT"].values[-1, 0])
    return (killed - last) % 1000


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--kills", type=int, default=5)
    p.add_argument("--flush", type=float, action="append", metavar="SECONDS")
    args = p.parse_args()
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "WallClock.py"), "w") as f:
            f.write(WALL_CLOCK)
        with open(os.path.join(folder, "loss.ikg"), "w") as f:
            f.write(MODEL)
        for flush in args.flush or [1.0]:
            lost = [one_kill(folder, flush) for _ in range(args.kills)]
            print(f"flush every {flush:g} s: lost {statistics.median(lost):.2f} s median, "
                  f"{max(lost):.2f} s at most, over {args.kills} kills "
                  f"(load average {load:.2f} before, {os.getloadavg()[0]:.2f} after)",
                  flush=True)


if __name__ == "__main__":
    main()
