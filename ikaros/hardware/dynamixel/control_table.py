"""Control tables of the Dynamixel series, read from the data files in ``tables/``.

Each JSON file describes one series: its models (name -> model number), protocol version,
the rows of the control table (``[address, size, name, access, default, only-these-models]``)
and the ``ikaros`` roles: which field holds, say, ``GOAL_POSITION`` and how its raw value
converts to the Ikaros unit, ``value = (raw - offset) * scale + bias`` (after sign decoding:
``bit10`` is sign-and-magnitude with bit 10 the direction, ``twos`` two's complement). A role
may name the models that have it (``models``) and per-model changes (``by_model``).
``goal_enables_torque`` marks a series whose servos switch their torque on when Goal Position
or Moving Speed is written (the Protocol 1.0 series).
Adding a series is adding a file.
"""
from __future__ import annotations

import functools
import json
import os
from dataclasses import dataclass, field as dataclass_field

from ikaros.hardware import DeviceError

TABLE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tables")


@dataclass(frozen=True)
class Field:
    name: str
    address: int
    size: int
    access: str
    default: int


@dataclass(frozen=True)
class Role:
    """How an Ikaros quantity is stored in one field."""
    field: Field
    scale: float = 1.0
    offset: float = 0.0
    bias: float = 0.0
    signed: str | None = None

    def to_value(self, raw: int) -> float:
        """Raw (unsigned, as read from the bus) to the Ikaros unit."""
        if self.signed == "bit10":
            raw = -(raw & 0x3FF) if raw & 0x400 else raw & 0x3FF
        elif self.signed == "twos" and raw >= 1 << (8 * self.field.size - 1):
            raw -= 1 << (8 * self.field.size)
        return (raw - self.offset) * self.scale + self.bias

    def to_raw(self, value: float) -> int:
        """Ikaros unit to the unsigned raw value written on the bus."""
        raw = int(round((value - self.bias) / self.scale + self.offset))
        if self.signed == "bit10":
            magnitude = min(abs(raw), 0x3FF)
            return magnitude | (0x400 if raw < 0 else 0)
        bits = 8 * self.field.size
        if self.signed == "twos":
            raw = max(-(1 << (bits - 1)), min((1 << (bits - 1)) - 1, raw))
            return raw & ((1 << bits) - 1)
        return max(0, min((1 << bits) - 1, raw))


@dataclass
class ControlTable:
    """The control table of one model."""
    series: str
    model: str
    model_number: int
    protocol: int
    fields: dict[str, Field]
    roles: dict[str, Role]
    no_load_rpm: float
    rpm_per_speed_unit: float
    baud_rates: dict[int, int] = dataclass_field(default_factory=dict)
    goal_enables_torque: bool = False   # writing Goal Position or Moving Speed turns torque on

    @property
    def size(self) -> int:
        return max(f.address + f.size for f in self.fields.values())

    def field(self, name: str) -> Field:
        try:
            return self.fields[name]
        except KeyError:
            raise DeviceError(f"the {self.model} has no control-table field '{name}'") from None

    def role(self, name: str) -> Role | None:
        return self.roles.get(name)

    def baud_code(self, baud_rate: int) -> int:
        for code, rate in self.baud_rates.items():
            if rate == baud_rate:
                return code
        known = ", ".join(str(r) for r in sorted(set(self.baud_rates.values())))
        raise DeviceError(f"the {self.model} cannot run at {baud_rate} baud (it can: {known})")

    def initial_memory(self) -> bytearray:
        """The control table filled with its default values (for the simulator)."""
        memory = bytearray(self.size)
        for f in self.fields.values():
            memory[f.address:f.address + f.size] = int(f.default).to_bytes(f.size, "little")
        memory[0:2] = self.model_number.to_bytes(2, "little")
        return memory


@functools.lru_cache(maxsize=None)
def _series_files() -> tuple[dict, ...]:
    found = []
    for name in sorted(os.listdir(TABLE_DIR)):
        if name.endswith(".json"):
            with open(os.path.join(TABLE_DIR, name), encoding="utf-8") as f:
                found.append(json.load(f))
    return tuple(found)


def _build(series: dict, model: str) -> ControlTable:
    fields = {}
    for row in series["table"]:
        address, size, name, access, default = row[:5]
        if len(row) > 5 and model not in row[5]:
            continue
        fields[name] = Field(name, address, size, access, default)
    roles = {}
    for role_name, spec in series["ikaros"].items():
        if "models" in spec and model not in spec["models"]:
            continue
        spec = {**spec, **spec.get("by_model", {}).get(model, {})}
        roles[role_name] = Role(fields[spec["field"]], spec.get("scale", 1.0), spec.get("offset", 0.0),
                                spec.get("bias", 0.0), spec.get("signed"))
    return ControlTable(series["series"], model, series["models"][model], series["protocol"], fields,
                        roles, series["no_load_rpm"][model], series["rpm_per_speed_unit"],
                        {int(k): v for k, v in series["baud_rates"].items()},
                        bool(series.get("goal_enables_torque", False)))


@functools.lru_cache(maxsize=None)
def table_for_model(model: str) -> ControlTable:
    """The control table of a model by name (e.g. ``"AX-12A"``, ``"XM430-W350"``)."""
    for series in _series_files():
        if model in series["models"]:
            return _build(series, model)
    raise DeviceError(f"unknown Dynamixel model '{model}' (known: {', '.join(all_models())})")


def table_for_number(model_number: int, protocol: int) -> ControlTable | None:
    """The control table of a model number read from a servo, or None for an unknown model."""
    for series in _series_files():
        if series["protocol"] != protocol:
            continue
        for model, number in series["models"].items():
            if number == model_number:
                return table_for_model(model)
    return None


def all_models() -> dict[str, int]:
    """Every known model name and its model number."""
    return {m: n for series in _series_files() for m, n in series["models"].items()}
