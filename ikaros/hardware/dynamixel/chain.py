"""The servos of a robot (a :class:`~ikaros.hardware.dynamixel.robot_config.Robot`) on their
buses, read and written by role as arrays in the robot's servo order.

Each bus is opened (or shared, :func:`~ikaros.hardware.dynamixel.servos.acquire_bus`) at its
port; a port ``sim:dynamixel?...`` starts the simulator. Every servo of the robot must answer
at the start and be the model its robot type names; otherwise opening fails with an error
naming the servo, its id, its bus and the port.
"""
from __future__ import annotations

import numpy as np

from ikaros.hardware import DeviceError
from ikaros.hardware.dynamixel.robot_config import Robot
from ikaros.hardware.dynamixel.servos import ServoGroup, open_bus, release_bus


class ServoChain:
    """The robot's servos, bus by bus; element k is ``robot.servos[k]``."""

    def __init__(self, robot: Robot, latency_ms: float | None = None):
        from ikaros.hardware.simulators import open_device_string
        self.robot = robot
        self.groups: dict[str, ServoGroup] = {}
        self.members: dict[str, list[tuple[int, int]]] = {}      # bus -> (element, id)
        self.simulators = []
        try:
            for element, servo in enumerate(robot.servos):
                self.members.setdefault(servo.bus, []).append((element, servo.ident))
            for bus_name, members in self.members.items():
                port = robot.ports[bus_name]
                device, simulator = open_device_string(port)
                if simulator is not None:
                    self.simulators.append(simulator)
                ids = [ident for _, ident in members]
                bus, tables = open_bus(device, robot.baud_rate, robot.protocol, ids, max(ids), latency_ms)
                self.groups[bus_name] = ServoGroup(bus, tables)
                self._check(bus_name, bus, tables)
        except BaseException:
            self.close()
            raise

    def _check(self, bus_name: str, bus, tables) -> None:
        for element, ident in self.members[bus_name]:
            servo = self.robot.servos[element]
            where = f"servo {servo.name} (id {ident} on the {bus_name} bus, {bus})"
            if ident not in tables:
                raise DeviceError(f"{where} does not answer")
            if tables[ident].model != servo.model:
                raise DeviceError(f"{where} is a {tables[ident].model}; the robot type {self.robot.kind} "
                                  f"says {servo.model}")

    def __repr__(self) -> str:
        return f"the {self.robot.name} ({', '.join(f'{n}: {g.bus}' for n, g in self.groups.items())})"

    def has(self, role: str) -> np.ndarray:
        """Which servos have the role (as booleans, element order)."""
        return np.array([s.table.role(role) is not None for s in self.robot.servos])

    def read(self, roles: list[str]) -> tuple[dict[str, np.ndarray], list[int]]:
        """Each role as an array in element order (NaN where a servo lacks it or does not
        answer), and the elements of the servos that did not answer."""
        out = {role: np.full(len(self.robot.servos), np.nan) for role in roles}
        missing = []
        for bus_name, group in self.groups.items():
            values, silent = group.read_available(roles)
            for element, ident in self.members[bus_name]:
                if ident in silent:
                    missing.append(element)
                for role in roles:
                    if ident in values[role]:
                        out[role][element] = values[role][ident]
        return out, sorted(missing)

    def write(self, role: str, values: dict[int, float]) -> None:
        """Write ``role`` of the servos whose elements are the keys (one sync write per bus
        and field layout); servos without the role are left out."""
        for bus_name, group in self.groups.items():
            chosen = {ident: values[element] for element, ident in self.members[bus_name] if element in values}
            if chosen:
                group.write(role, chosen)

    def safe_state(self) -> list[str]:
        """Torque off on every servo that answers; the names of those that did not."""
        failed = []
        for bus_name, group in self.groups.items():
            names = {ident: self.robot.servos[e].name for e, ident in self.members[bus_name]}
            failed += [names[ident] for ident in group.safe_state("torque_off")]
        return failed

    def close(self) -> None:
        for group in self.groups.values():
            release_bus(group.bus)
        self.groups = {}
        for simulator in self.simulators:
            simulator.stop()
        self.simulators = []
