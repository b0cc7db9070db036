"""Find the Dynamixel servos on a bus: every baud rate, both protocols.

    python -m ikaros.hardware.dynamixel.scan /dev/ttyUSB0
    python -m ikaros.hardware.dynamixel.scan /dev/ttyUSB0 --baud 57600 1000000 --max-id 20

prints one line per servo found: id, model, protocol and baud rate.
"""
from __future__ import annotations

import argparse
import sys

from ikaros.hardware import DeviceError
from ikaros.hardware.dynamixel.bus import DynamixelBus
from ikaros.hardware.dynamixel.control_table import table_for_number

COMMON_BAUD_RATES = [57600, 1000000, 115200, 2000000, 3000000, 9600]


def scan(device: str, baud_rates=COMMON_BAUD_RATES, max_id: int = 32, protocols=(1, 2),
         latency_ms: float | None = None) -> list[tuple]:
    """(id, model name, protocol, baud rate) of every servo that answers (``latency_ms``: how
    long the adapter may hold a packet, which sets how long an answer is waited for)."""
    found = []
    for baud in baud_rates:
        bus = DynamixelBus(device, baud, protocols[0], latency_ms)
        try:
            for protocol in protocols:
                bus.set_protocol(protocol)
                for ident, number in bus.scan(range(0, max_id + 1)).items():
                    table = table_for_number(number, protocol)
                    found.append((ident, table.model if table else f"model number {number}", protocol, baud))
        finally:
            bus.close()
    return found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m ikaros.hardware.dynamixel.scan", description=__doc__.split("\n\n")[0])
    parser.add_argument("device", help="the serial device, e.g. /dev/ttyUSB0")
    parser.add_argument("--baud", type=int, nargs="+", default=COMMON_BAUD_RATES, help="baud rates to try")
    parser.add_argument("--max-id", type=int, default=32, help="the highest id to ping (default 32)")
    parser.add_argument("--protocol", type=int, choices=(1, 2), help="only this protocol version")
    parser.add_argument("--latency", type=float, default=None, metavar="MS",
                        help="milliseconds the adapter may hold a packet (default 16; more on a busy machine)")
    options = parser.parse_args(argv)
    try:
        found = scan(options.device, options.baud, options.max_id,
                     (options.protocol,) if options.protocol else (1, 2), options.latency)
    except DeviceError as error:
        print(f"scan: {error}", file=sys.stderr)
        return 1
    for ident, model, protocol, baud in found:
        print(f"id {ident:3d}  {model:14s}  Protocol {protocol}.0  {baud} baud")
    if not found:
        print("no servo answered (check power, cable and the device name; see docs/robots.md)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
