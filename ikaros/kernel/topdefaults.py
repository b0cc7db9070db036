"""The defaults of the top group's settings: what the kernel uses when a model sets none,
and what ``@tick_duration``, ``@stop`` ... resolve to then (a variable's lookup ends with
them, as in Ikaros 3)."""
from __future__ import annotations

# seconds, when a model sets none: Ikaros 2 files get 0.01, Ikaros 3 files Ikaros 3's 1 s
DEFAULT_TICK_DURATION = {"2": 0.01, "3": 1.0}


def top_level_defaults(dialect: str, filename: str) -> dict[str, str]:
    """The top-level settings' values when the top group does not set them."""
    return {"tick_duration": f"{DEFAULT_TICK_DURATION[dialect]:g}", "stop": "-1",
            "filename": filename, "batch_mode": "false", "info": "false",
            "real_time": "false", "start": "false"}
