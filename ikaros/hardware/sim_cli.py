"""The `ikaros-sim` command: run a device simulator and print the device path a driver opens.

    ikaros-sim dynamixel --ids 1-19 --protocol 2

prints the path (e.g. ``/dev/pts/7``) on the first line of standard output and runs until
Ctrl-C. See :mod:`ikaros.hardware.simulators` for adding a simulator.
"""
from __future__ import annotations

import argparse
import signal
import sys
import threading

from ikaros.hardware import DeviceError
from ikaros.hardware.simulators import SIMULATORS, make_parser, simulator_module


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="ikaros-sim",
        description="Simulated robot hardware speaking the real protocols, on this machine only.")
    commands = parser.add_subparsers(dest="simulator", required=True, metavar="SIMULATOR")
    for name in SIMULATORS:
        make_parser(name, commands.add_parser(name, help=simulator_module(name).HELP))
    return parser


def main(argv: list[str] | None = None) -> int:
    options = build_parser().parse_args(argv)
    finished = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: finished.set())   # before the device: never killed by -15
    try:
        device = simulator_module(options.simulator).start(options)
    except DeviceError as error:
        print(f"ikaros-sim: {error}", file=sys.stderr)
        return 1
    print(device.path, flush=True)
    print(f"{options.simulator} simulator at {device.path}; Ctrl-C stops it", file=sys.stderr, flush=True)
    try:
        while not finished.wait(0.2):
            pass
    except KeyboardInterrupt:
        pass
    finally:
        device.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
