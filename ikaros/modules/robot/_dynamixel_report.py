"""The state of every servo of a Dynamixel bus as a table, printed when a servo overheats."""
from __future__ import annotations

COLUMNS = [("PRESENT_POSITION", "position", "{:8.1f}°"), ("PRESENT_LOAD", "load", "{:6.2f}"),
           ("PRESENT_VOLTAGE", "voltage", "{:6.1f} V"), ("PRESENT_TEMPERATURE", "temperature", "{:6.0f} °C"),
           ("TORQUE_ENABLE", "torque", "{:>4.0f}"), ("TORQUE_LIMIT", "torque limit", "{:6.2f}")]


def state_table(tables: dict, values: dict[str, dict[int, float]]) -> str:
    """One line per servo (id, model, then each value of ``values`` it has: role -> id ->
    value), under a heading."""
    lines = ["servo  model         " + "  ".join(f"{title:>11}" for _, title, _ in COLUMNS)]
    for ident, table in tables.items():
        cells = []
        for role, _, form in COLUMNS:
            value = values.get(role, {}).get(ident)
            cells.append(f"{form.format(value) if value is not None else '-':>11}")
        lines.append(f"{ident:5d}  {table.model:12s}  " + "  ".join(cells))
    return "\n".join(lines)
