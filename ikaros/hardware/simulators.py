"""The registry of device simulators, shared by the `ikaros-sim` command and model attributes.

A device attribute of the form ``sim:NAME?option=value&option=value`` (for example
``device="sim:dynamixel?ids=1-19&protocol=2"``) starts simulator NAME in the running process;
the options are those of ``ikaros-sim NAME --help`` without the dashes, and a bare flag is
written ``flag`` or ``flag=1``.

Adding a simulator: write a module with

* ``HELP``: one line for ``ikaros-sim --help``;
* ``add_arguments(parser)``: its options on an ``argparse.ArgumentParser``;
* ``start(options) -> device``: start it from the parsed ``argparse.Namespace`` and return it;
  the device has ``path`` (what a driver opens: a device path, or ``host:port`` for a socket)
  and ``stop()``;

and add its name and module path to :data:`SIMULATORS`.
"""
from __future__ import annotations

import argparse
import importlib
from types import ModuleType
from typing import Any
from urllib.parse import parse_qsl

from ikaros.hardware import DeviceError

SIMULATORS: dict[str, str] = {
    "dynamixel": "ikaros.hardware.dynamixel.simulator_options",
    "ssc32": "ikaros.hardware.ssc32_sim",
    "opc": "ikaros.hardware.opc_sim",
    "epuck": "ikaros.hardware.epuck_sim",
    "um7": "ikaros.hardware.um7_sim",
}

PREFIX = "sim:"


def is_simulated(device: str) -> bool:
    """True when a device attribute names a simulator rather than a real device."""
    return device.strip().startswith(PREFIX)


def open_device_string(device: str) -> tuple[str, Any]:
    """What a driver opens for its device attribute, and the simulator started for it:
    ``(path, simulator)`` for ``sim:NAME?options``, ``(device, None)`` for a real device."""
    if not is_simulated(device):
        return device, None
    simulator = start_from_device_string(device)
    return simulator.path, simulator


def simulator_module(name: str) -> ModuleType:
    if name not in SIMULATORS:
        known = ", ".join(sorted(SIMULATORS))
        raise DeviceError(f"no simulator called '{name}' (known: {known})")
    return importlib.import_module(SIMULATORS[name])


def make_parser(name: str, parser: argparse.ArgumentParser | None = None) -> argparse.ArgumentParser:
    module = simulator_module(name)
    parser = parser or argparse.ArgumentParser(prog=f"{PREFIX}{name}", add_help=False,
                                               exit_on_error=False)
    module.add_arguments(parser)
    return parser


def start_from_device_string(device: str):
    """Start the simulator a ``sim:NAME?options`` device string names; returns the started device."""
    name, _, query = device.strip()[len(PREFIX):].partition("?")
    argv: list[str] = []
    try:
        pairs = parse_qsl(query, keep_blank_values=True, strict_parsing=bool(query))
    except ValueError:
        raise DeviceError(f"cannot read the simulator options in '{device}'") from None
    for key, value in pairs:
        argv.append("--" + key.replace("_", "-"))
        if value:
            argv.append(value)
    parser = make_parser(name)
    try:
        options = parser.parse_args(argv)
    except (argparse.ArgumentError, SystemExit) as error:
        raise DeviceError(f"bad simulator options in '{device}': {error}") from None
    return simulator_module(name).start(options)
