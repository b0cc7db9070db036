"""What the Dynamixel module writes each tick, in Ikaros 2's order, and the torque ramp.

Ikaros 2 writes, within a tick: TORQUE_ENABLE, LED, D_GAIN, I_GAIN, P_GAIN, GOAL_POSITION,
MOVING_SPEED, TORQUE_LIMIT, GOAL_TORQUE, GOAL_ACCELERATION. A goal position or moving speed
makes a Protocol 1.0 servo switch its torque on, so neither is written to a servo whose
TORQUE_ENABLE input is 0. The torque limit written is the TORQUE_LIMIT input times a
multiplier that ramps from 0 to 1 over ``torque_up_delay`` ticks.
"""
from __future__ import annotations

import math

SETTINGS = ["TORQUE_ENABLE", "LED", "D_GAIN", "I_GAIN", "P_GAIN", "GOAL_POSITION", "MOVING_SPEED",
            "TORQUE_LIMIT", "GOAL_TORQUE", "GOAL_ACCELERATION"]
NEEDS_TORQUE = ("GOAL_POSITION", "MOVING_SPEED")    # writing these turns a 1.0 servo's torque on


def ramp(tick: int, start: int, ticks: int) -> float:
    """The torque-limit multiplier on ``tick`` of a ramp that begins on tick ``start`` and
    lasts ``ticks`` ticks: (tick - start) / ticks, between 0 and 1 (1 without a ramp)."""
    if ticks <= 0:
        return 1.0
    return min(max((tick - start) / ticks, 0.0), 1.0)


class SettingsWriter:
    """Writes the settings of a :class:`~ikaros.hardware.dynamixel.servos.ServoGroup` and
    remembers, per role and servo, the raw value last written; with ``optimize`` only a
    value whose raw value changed is sent again."""

    def __init__(self, group, optimize: bool, publish):
        self.group = group
        self.optimize = optimize
        self.publish = publish              # publish(role, {id: value}) after a write
        self.raw: dict[str, dict[int, int]] = {role: {} for role in SETTINGS}

    def remember(self, role: str, values: dict[int, float]) -> None:
        """Values the servos hold without this writer having written them (read at start)."""
        for ident, value in values.items():
            entry = self.group.tables[ident].role(role)
            if entry is not None and math.isfinite(value):
                self.raw[role][ident] = entry.to_raw(value)

    def forget(self, role: str) -> None:
        """The servos may hold other values now: send the next ones whatever they are."""
        self.raw[role] = {}

    def write(self, role: str, values: dict[int, float]) -> dict[int, float]:
        """Write ``values`` (the changed ones with ``optimize``) in one sync write per field
        layout; returns what was written."""
        send = {}
        for ident, value in values.items():
            entry = self.group.tables[ident].role(role)
            if entry is None or not math.isfinite(value):
                continue
            raw = entry.to_raw(value)
            if self.optimize and self.raw[role].get(ident) == raw:
                continue
            send[ident] = value
            self.raw[role][ident] = raw
        if send:
            self.group.write(role, send)
            self.publish(role, send)
        return send
