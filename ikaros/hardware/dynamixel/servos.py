"""A group of Dynamixel servos on one bus, read and written by role in Ikaros units.

Roles are the names of the control-table files (``GOAL_POSITION``, ``PRESENT_LOAD``, ...).
Servos whose fields lie at the same addresses share one sync write or sync read packet;
positions are in degrees (180 is the centre), the other roles in the units of
:mod:`ikaros.hardware.dynamixel.control_table`.
"""
from __future__ import annotations

import os
import threading

from ikaros.hardware import DeviceError
from ikaros.hardware.dynamixel import protocol as p
from ikaros.hardware.dynamixel.bus import DynamixelBus, NoReply
from ikaros.hardware.dynamixel.control_table import ControlTable, table_for_number


_open_buses: dict[str, list] = {}      # real device path -> [bus, number of users]
_open_lock = threading.Lock()


def acquire_bus(device: str, baud_rate: int, protocol: int, latency_ms: float | None = None) -> DynamixelBus:
    """The open bus on ``device``, shared by every driver that uses it (two modules on one bus,
    or a model rebuilt by the web UI while the old one still runs); opened on first use. Give it
    back with :func:`release_bus`."""
    key = os.path.realpath(device) if not device.startswith("sim:") else device
    with _open_lock:
        entry = _open_buses.get(key)
        if entry is not None:
            if entry[0].baud_rate != int(baud_rate):
                raise DeviceError(f"the Dynamixel bus at '{device}' is already open at {entry[0].baud_rate} "
                                  f"baud; it cannot also run at {baud_rate}")
            entry[1] += 1
            return entry[0]
        bus = DynamixelBus(device, baud_rate, protocol, latency_ms)
        _open_buses[key] = [bus, 1]
        return bus


def release_bus(bus: DynamixelBus) -> None:
    """Give a bus back; the last user closes it."""
    with _open_lock:
        for key, entry in list(_open_buses.items()):
            if entry[0] is bus:
                entry[1] -= 1
                if entry[1] > 0:
                    return
                del _open_buses[key]
    bus.close()


def open_bus(device: str, baud_rate: int, protocol: str | int = "auto", ids=None, max_id: int = 32,
             latency_ms: float | None = None, force_model: int = 0) -> tuple[DynamixelBus, dict[int, ControlTable]]:
    """Open a bus (or share the one already open on ``device``) and find its servos: the given
    ``ids`` (None: scan 0..max_id), in the given protocol (``auto``: ping with Protocol 1.0, then
    2.0; a bus that mixes them is refused). A servo of a model without a control table is
    refused, or taken as ``force_model``. Give the bus back with :func:`release_bus`."""
    ids_given = ids is not None
    ids = list(range(0, max_id + 1)) if ids is None else list(ids)
    protocols = [1, 2] if str(protocol) == "auto" else [int(float(protocol))]
    bus = acquire_bus(device, baud_rate, protocols[0], latency_ms)
    try:
        with bus.lock:
            return bus, _find_servos(bus, device, baud_rate, protocols, ids, force_model, named=ids_given)
    except BaseException:
        release_bus(bus)
        raise


def _find_servos(bus, device, baud_rate, protocols, ids, force_model, named) -> dict[int, ControlTable]:
    found: dict[int, dict[int, int]] = {}
    in_use = bus.protocol
    for version in protocols:
        bus.set_protocol(version)
        found[version] = bus.scan(ids)
        if named:                               # a servo the model names gets a second chance
            found[version].update(bus.scan([i for i in ids if i not in found[version]]))
    answered = {v: f for v, f in found.items() if f}
    if len(answered) > 1:
        raise DeviceError(f"the Dynamixel bus at '{device}' mixes Protocol 1.0 servos "
                          f"{sorted(answered[1])} and Protocol 2.0 servos {sorted(answered[2])}; "
                          f"give each protocol its own bus")
    if not answered:
        bus.set_protocol(in_use)
        raise DeviceError(f"no Dynamixel servo answers on '{device}' at {baud_rate} baud "
                          f"(ids {_ranges(ids)}, Protocol {' and '.join(f'{v}.0' for v in protocols)}); "
                          f"check power, cable, baud rate and ids (see docs/robots.md)")
    version, servos = next(iter(answered.items()))
    bus.set_protocol(version)
    tables = {}
    for ident, number in servos.items():
        table = table_for_number(number, version) or (table_for_number(force_model, version) if force_model else None)
        if table is None:
            raise DeviceError(f"servo {ident} on {bus} is model number {number}, which has no "
                              f"control table here (add one in ikaros/hardware/dynamixel/tables)")
        tables[ident] = table
    return tables


def _ranges(ids) -> str:
    ids = sorted(ids)
    return f"{ids[0]}..{ids[-1]}" if ids and ids == list(range(ids[0], ids[-1] + 1)) else ", ".join(map(str, ids))


class ServoGroup:
    """The servos ``tables`` (id -> control table) on ``bus``; all traffic under the bus's lock."""

    def __init__(self, bus: DynamixelBus, tables: dict[int, ControlTable]):
        self.bus = bus
        self.tables = dict(sorted(tables.items()))
        self.ids = list(self.tables)
        self.lock = bus.lock

    def has(self, ident: int, role: str) -> bool:
        return self.tables[ident].role(role) is not None

    def read(self, roles: list[str], ids=None) -> dict[str, dict[int, float]]:
        """Values of ``roles`` for each servo (those a model lacks are left out), with one
        sync read per group of servos that share a layout (Protocol 2.0). A servo that does
        not answer (after a retry) raises :class:`NoReply` naming it and the register."""
        values, missing = self.read_available(roles, ids)
        if missing:
            ident, register = next(iter(missing.items()))
            raise NoReply(f"servo {ident} on {self.bus} does not answer (reading {register})")
        return values

    def read_available(self, roles: list[str], ids=None) -> tuple[dict[str, dict[int, float]], dict[int, str]]:
        """As :meth:`read`, but a servo that does not answer is left out: the values of those
        that answered, and id -> the register (name and address) of each that did not."""
        ids = self.ids if ids is None else list(ids)
        out: dict[str, dict[int, float]] = {role: {} for role in roles}
        missing: dict[int, str] = {}
        for (start, length), members in self._blocks(roles, ids).items():
            register = self.register(members[0], start, length)
            with self.lock:
                if self.bus.protocol == 1 and len(members) > 1 and all(
                        self.tables[i].series.startswith("MX") for i in members):
                    data = self.bus.bulk_read([(i, start, length) for i in members], register)   # one packet
                else:
                    data = self.bus.sync_read(start, length, members, register)
            for ident in members:
                if ident not in data:
                    missing[ident] = register
                    continue
                table = self.tables[ident]
                for role in roles:
                    entry = table.role(role)
                    if entry is None:
                        continue
                    at = entry.field.address - start
                    raw = int.from_bytes(data[ident][at:at + entry.field.size], "little")
                    out[role][ident] = entry.to_value(raw)
        return out, dict(sorted(missing.items()))

    def register(self, ident: int, start: int, length: int) -> str:
        """The control-table fields of servo ``ident`` in bytes start..start+length, by name and
        address: ``Present Position, address 132``, or ``Present Current to Present
        Temperature, addresses 126..146``."""
        fields = sorted((f for f in self.tables[ident].fields.values()
                         if start <= f.address and f.address + f.size <= start + length),
                        key=lambda f: f.address)
        if not fields:
            return f"{length} bytes at address {start}"
        if len(fields) == 1:
            return f"{fields[0].name}, address {fields[0].address}"
        return f"{fields[0].name} to {fields[-1].name}, addresses {start}..{fields[-1].address}"

    def _blocks(self, roles, ids) -> dict[tuple[int, int], list[int]]:
        blocks: dict[tuple[int, int], list[int]] = {}
        for ident in ids:
            fields = [e.field for e in (self.tables[ident].role(r) for r in roles) if e is not None]
            if not fields:
                continue
            start = min(f.address for f in fields)
            end = max(f.address + f.size for f in fields)
            blocks.setdefault((start, end - start), []).append(ident)
        return blocks

    def write(self, role: str, values: dict[int, float]) -> None:
        """Write ``role`` of each servo in ``values``: one sync write per field layout."""
        groups: dict[tuple[int, int], dict[int, bytes]] = {}
        for ident, value in values.items():
            entry = self.tables[ident].role(role)
            if entry is None:
                continue
            f = entry.field
            groups.setdefault((f.address, f.size), {})[ident] = entry.to_raw(value).to_bytes(f.size, "little")
        with self.lock:
            for (address, size), data in groups.items():
                self.bus.sync_write(address, size, data)

    def write_each(self, role: str, values: dict[int, float]) -> dict[int, DeviceError]:
        """Write ``role`` servo by servo, waiting for each status; returns the servos that failed
        (the others are written even when some do not answer)."""
        failures = {}
        for ident, value in values.items():
            entry = self.tables[ident].role(role)
            if entry is None:
                continue
            f = entry.field
            try:
                with self.lock:
                    self.bus.write(ident, f.address, entry.to_raw(value).to_bytes(f.size, "little"),
                                   f"{f.name}, address {f.address}")
            except DeviceError as error:
                failures[ident] = error
        return failures

    def error_text(self, ident: int, error: int) -> str:
        """The status error byte of a servo in words."""
        if self.bus.protocol == 1:
            names = [name for bit, name in p.P1_ERROR_NAMES.items() if error & bit]
        else:
            names = [p.P2_ERROR_NAMES[error & 0x7F]] if error & 0x7F in p.P2_ERROR_NAMES else []
            if error & p.P2_ALERT:
                names.append("hardware alert")
        return ", ".join(names)

    def safe_state(self, mode: str) -> dict[int, DeviceError]:
        """Torque off (``torque_off``) or hold the present position (``hold``) on every servo
        that answers; returns the servos that did not."""
        with self.lock:
            if mode == "hold":
                failures = {}
                present = {}
                for ident in self.ids:
                    try:
                        present.update(self.read(["PRESENT_POSITION"], [ident])["PRESENT_POSITION"])
                    except DeviceError as error:
                        failures[ident] = error
                failures.update(self.write_each("GOAL_POSITION", present))
                return failures
            return self.write_each("TORQUE_ENABLE", {ident: 0 for ident in self.ids})
