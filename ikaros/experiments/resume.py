"""Resuming a sweep: a second ``sweep`` into the same folder runs only the runs the first
did not finish.

Beside the results table the folder holds ``sweep.json``: what decides the runs (the
model's text, the grid of settings, ticks, recorded patterns, every). When it matches, the
rows of the table whose status is "ok" or "error" are kept (a failed run failed after its
retries) and so are their recordings; runs missing from the table or "interrupted" run
again. When it does not match, every run runs.
"""
from __future__ import annotations

import hashlib
import json
import os

SIGNATURE_FILE = "sweep.json"
KEPT = ("ok", "error")


def signature(model_text: str, settings: dict, ticks: int, record: list,
              every: int) -> dict:
    """What decides a sweep's runs, as JSON can hold it."""
    return {"model_sha256": hashlib.sha256(model_text.encode()).hexdigest(),
            "settings": {k: [_plain(v) for v in values] for k, values in settings.items()},
            "ticks": int(ticks), "record": list(record), "every": int(every)}


def _plain(value):
    return value.item() if hasattr(value, "item") else value


def write_signature(out: str, sign: dict) -> None:
    with open(os.path.join(out, SIGNATURE_FILE), "w", encoding="utf-8") as f:
        json.dump(sign, f, indent=1)


def done_before(out: str, table_format: str, sign: dict, specs: list) -> dict:
    """{run index: row} of the runs a sweep with the same signature already did in
    ``out`` (empty when there was none, or another)."""
    try:
        with open(os.path.join(out, SIGNATURE_FILE), encoding="utf-8") as f:
            if json.load(f) != sign:
                return {}
        table = read_table(out, table_format)
    except (OSError, ValueError):
        return {}
    by_index = {spec.index: spec for spec in specs}
    kept = {}
    for row in table.to_dict("records"):
        spec = by_index.get(int(row.get("run", -1)))
        if spec is None or row.get("status") not in KEPT or \
                any(row.get(k) != v for k, v in spec.settings.items()):
            continue
        if row["status"] == "ok" and spec.recording and not os.path.exists(spec.recording):
            continue
        kept[spec.index] = row
    return kept


def read_table(out: str, table_format: str):
    import pandas as pd
    path = os.path.join(out, f"results.{table_format}")
    return pd.read_csv(path) if table_format == "csv" else pd.read_parquet(path)
