"""Sequences of keyframes for Ikaros 3's SequenceRecorder: per channel a list of (time in
seconds, value), read at any time by step or linear interpolation, simplified after recording,
and kept in JSON files."""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field


@dataclass
class Sequence:
    name: str
    channels: list[list[tuple[float, float]]] = field(default_factory=list)   # per channel, sorted by time

    def end(self) -> float:
        """The time of the last keyframe of any channel (0 when empty)."""
        return max((keys[-1][0] for keys in self.channels if keys), default=0.0)

    def has(self, channel: int) -> bool:
        return channel < len(self.channels) and bool(self.channels[channel])

    def value(self, channel: int, time: float, linear: bool) -> float | None:
        """The channel's value at ``time`` (None without keyframes): before the first keyframe
        its value, after the last its value, between two the earlier one's (step) or a
        straight line between them (linear)."""
        if not self.has(channel):
            return None
        keys = self.channels[channel]
        if time <= keys[0][0]:
            return keys[0][1]
        for (t0, v0), (t1, v1) in zip(keys, keys[1:]):
            if time < t1:
                if not linear or t1 <= t0:
                    return v0
                return v0 + (v1 - v0) * (time - t0) / (t1 - t0)
        return keys[-1][1]

    def replace(self, channel: int, start: float, end: float, keys: list[tuple[float, float]]) -> None:
        """The channel's keyframes from ``start`` to ``end`` become ``keys``."""
        while len(self.channels) <= channel:
            self.channels.append([])
        kept = [k for k in self.channels[channel] if not start <= k[0] <= end]
        self.channels[channel] = sorted(kept + keys)

    def to_json(self) -> dict:
        return {"name": self.name, "channels": [[list(k) for k in keys] for keys in self.channels]}

    @staticmethod
    def from_json(data: dict, name: str) -> "Sequence":
        channels = [sorted((float(t), float(v)) for t, v in keys) for keys in data.get("channels", [])]
        return Sequence(str(data.get("name", name)), channels)


def simplify(keys: list[tuple[float, float]], epsilon: float) -> list[tuple[float, float]]:
    """Ramer-Douglas-Peucker on (time, value): the fewest keyframes whose straight lines stay
    within ``epsilon`` of every value left out (the first and the last are kept)."""
    if len(keys) < 3 or epsilon <= 0:
        return list(keys)
    (t0, v0), (t1, v1) = keys[0], keys[-1]
    worst, where = -1.0, 0
    for k in range(1, len(keys) - 1):
        t, v = keys[k]
        line = v0 if t1 == t0 else v0 + (v1 - v0) * (t - t0) / (t1 - t0)
        if abs(v - line) > worst:
            worst, where = abs(v - line), k
    if worst <= epsilon:
        return [keys[0], keys[-1]]
    return simplify(keys[:where + 1], epsilon)[:-1] + simplify(keys[where:], epsilon)


def clock_text(seconds: float) -> str:
    """``MM:SS:mmm``, as Ikaros 3's time parameters are written."""
    milliseconds = int(round(max(seconds, 0.0) * 1000.0))
    return f"{milliseconds // 60000:02d}:{milliseconds // 1000 % 60:02d}:{milliseconds % 1000:03d}"


def clock_seconds(text: str) -> float:
    """The seconds of ``MM:SS:mmm`` (or a plain number of seconds)."""
    parts = str(text).strip().split(":")
    try:
        if len(parts) == 3:
            return int(parts[0]) * 60 + int(parts[1]) + int(parts[2]) / 1000.0
        return float(parts[0])
    except ValueError:
        raise ValueError(f"cannot read the time '{text}' (write MM:SS:mmm)") from None


def load_sequences(path: str) -> list[Sequence]:
    """The sequences of a JSON file: {"sequences": [{"name", "channels": [[[t, v], ...], ...]}]}
    (or one such sequence)."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    items = data.get("sequences", [data]) if isinstance(data, dict) else []
    return [Sequence.from_json(item, f"Sequence {k + 1}") for k, item in enumerate(items)]


def save_sequences(path: str, sequences: list[Sequence]) -> None:
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump({"sequences": [s.to_json() for s in sequences]}, f, indent=1)
