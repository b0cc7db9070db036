"""`ikaros-sim dynamixel` and ``device="sim:dynamixel?..."``: options of the virtual Dynamixel bus."""
from __future__ import annotations

import argparse

from ikaros.hardware import DeviceError
from ikaros.hardware.dynamixel.simulator import DEFAULT_MODEL, VirtualDynamixelBus, parse_ids

HELP = "a Dynamixel bus of simulated servos (Protocol 1.0 or 2.0)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--ids", default="1", help="servo ids, e.g. 1-19 or 1,2,5 (default 1)")
    parser.add_argument("--protocol", type=int, choices=(1, 2), default=2, help="protocol version (default 2)")
    parser.add_argument("--model", default=None,
                        help="servo model for all ids (default AX-12A for Protocol 1, XM430-W350 for 2)")
    parser.add_argument("--servo", action="append", default=[], metavar="ID=MODEL",
                        help="a different model for one id (repeatable), e.g. --servo 3=MX-28")
    parser.add_argument("--baud", type=int, default=1000000, help="baud rate the servos are set to (default 1000000)")
    parser.add_argument("--line-time", action="store_true",
                        help="every packet takes the time it would take on the wire at the port's baud rate")


def start(options: argparse.Namespace) -> VirtualDynamixelBus:
    try:
        model = options.model or DEFAULT_MODEL[options.protocol]
        servos = {ident: model for ident in parse_ids(options.ids)}
        for entry in options.servo:
            ident, _, name = entry.partition("=")
            servos[int(ident)] = name.strip()
        bus = VirtualDynamixelBus(servos, options.protocol, options.baud, line_time=options.line_time)
    except (ValueError, DeviceError) as error:
        raise DeviceError(f"cannot start the Dynamixel simulator: {error}") from None
    return bus.start()
