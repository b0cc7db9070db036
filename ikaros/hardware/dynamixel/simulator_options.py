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
    parser.add_argument("--silent", default="", metavar="IDS",
                        help="fault: these servos never answer, e.g. 3 or 2-4")
    parser.add_argument("--load", action="append", default=[], metavar="ID=FRACTION",
                        help="an external load on a servo as a signed fraction of its maximum torque "
                             "(above 1: overload), e.g. --load 2=0.5 (repeatable)")
    parser.add_argument("--temperature", action="append", default=[], metavar="ID=CELSIUS",
                        help="a servo and its surroundings at this temperature, e.g. --temperature 2=65 "
                             "(repeatable)")


def start(options: argparse.Namespace) -> VirtualDynamixelBus:
    try:
        model = options.model or DEFAULT_MODEL[options.protocol]
        servos = {ident: model for ident in parse_ids(options.ids)}
        for entry in options.servo:
            ident, _, name = entry.partition("=")
            servos[int(ident)] = name.strip()
        bus = VirtualDynamixelBus(servos, options.protocol, options.baud, line_time=options.line_time)
        bus.silence(*parse_ids(options.silent))
        for entry in options.load:
            ident, _, fraction = entry.partition("=")
            bus.set_external_load(int(ident), float(fraction))
        for entry in options.temperature:
            ident, _, celsius = entry.partition("=")
            bus.set_temperature(int(ident), float(celsius))
    except (ValueError, KeyError, DeviceError) as error:
        raise DeviceError(f"cannot start the Dynamixel simulator: {error}") from None
    return bus.start()
