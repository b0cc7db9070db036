"""Robot configurations: which Dynamixel servos a robot has, on which buses, and its ports.

Two kinds of JSON file, in ``robots/`` beside this module or in a folder ``robots`` beside a
model (which wins, so a user adds or overrides a robot by adding a file):

* a **robot type** (``robots/types/NAME.json``): ``type``, ``description``, ``protocol``,
  ``baud_rate``, ``buses`` (their names, in order) and ``servos``: a list of ``{"name",
  "bus", "id", "model"}``, with optional ``"min"`` and ``"max"`` (degrees; 180 is a servo's
  centre), in the order of the driver's elements;
* a **robot** (``robots/NAME.json``): ``robot``, ``type``, ``description`` and ``ports``:
  the serial device of each bus (``/dev/ttyUSB0``, or ``sim:dynamixel?...`` for the
  simulator); optionally ``baud_rate`` to override the type's.

Adding a robot is adding a file; adding a kind of robot is adding a type file.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass

from ikaros.hardware import DeviceError
from ikaros.hardware.dynamixel.control_table import ControlTable, table_for_model

ROBOT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "robots")


@dataclass(frozen=True)
class ServoSpec:
    name: str
    bus: str
    ident: int
    model: str
    low: float | None = None
    high: float | None = None

    @property
    def table(self) -> ControlTable:
        return table_for_model(self.model)


@dataclass(frozen=True)
class Robot:
    name: str
    kind: str
    description: str
    protocol: int
    baud_rate: int
    ports: dict[str, str]
    servos: tuple[ServoSpec, ...]

    def index(self, servo_name: str) -> int:
        """The element of the servo called ``servo_name``."""
        for k, servo in enumerate(self.servos):
            if servo.name == servo_name:
                return k
        raise DeviceError(f"the robot {self.name} has no servo called '{servo_name}' "
                          f"(it has {', '.join(s.name for s in self.servos)})")


def folders(model_folder: str | None) -> list[str]:
    """Where robot files are looked for: ``robots`` beside the model first, then the package's."""
    found = [os.path.join(model_folder, "robots")] if model_folder else []
    return found + [ROBOT_DIR]


def _read(path: str) -> dict:
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except json.JSONDecodeError as error:
        raise DeviceError(f"the robot file {path} is not valid JSON: {error}") from None


def _find(name: str, places: list[str]) -> str | None:
    for place in places:
        path = os.path.join(place, name + ".json")
        if os.path.isfile(path):
            return path
    return None


def known_robots(model_folder: str | None = None) -> list[str]:
    """The names of the robots that have a file."""
    names = set()
    for place in folders(model_folder):
        if os.path.isdir(place):
            names.update(f[:-5] for f in os.listdir(place) if f.endswith(".json"))
    return sorted(names)


def robot_type(kind: str, model_folder: str | None = None) -> dict:
    """The robot type ``kind`` as read from its file."""
    places = [os.path.join(p, "types") for p in folders(model_folder)]
    path = _find(kind, places)
    if path is None:
        raise DeviceError(f"no robot type '{kind}' (a file types/{kind}.json in {' or '.join(places)})")
    return _read(path)


def load_robot(name: str, model_folder: str | None = None) -> Robot:
    """The robot ``name``: its file, and the file of its type."""
    path = _find(name, folders(model_folder))
    if path is None:
        raise DeviceError(f"no robot called '{name}' (known: {', '.join(known_robots(model_folder)) or 'none'}; "
                          f"add one as {name}.json in a folder 'robots' beside the model)")
    return _assemble(_read(path), path, name, model_folder)


def robot_with_ports(kind: str, ports: dict[str, str], model_folder: str | None = None) -> Robot:
    """A robot of type ``kind`` at the given ports (for drivers that take a port, not a robot)."""
    return _assemble({"robot": kind, "type": kind, "ports": ports}, f"types/{kind}.json", kind, model_folder)


def _assemble(robot: dict, path: str, name: str, model_folder: str | None) -> Robot:
    try:
        kind = robot_type(robot["type"], model_folder)
        servos = tuple(ServoSpec(s["name"], s["bus"], int(s["id"]), s["model"], s.get("min"), s.get("max"))
                       for s in kind["servos"])
        ports = dict(robot.get("ports", {}))
        for servo in servos:
            servo.table                                     # an unknown model fails here
            if servo.bus not in ports:
                raise DeviceError(f"servo {servo.name} is on the bus '{servo.bus}', which has no port")
        return Robot(robot.get("robot", name), kind["type"], kind.get("description", ""), int(kind["protocol"]),
                     int(robot.get("baud_rate", kind["baud_rate"])), ports, servos)
    except KeyError as missing:
        raise DeviceError(f"the robot file {path} (or its type) lacks {missing}") from None
    except DeviceError as error:
        raise DeviceError(f"the robot file {path}: {error}") from None
