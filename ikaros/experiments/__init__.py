"""Experiments: recording runs into HDF5, reading them as xarray Datasets, plots, replay,
progress and parameter sweeps. Depends on the kernel only (the kernel does not import it:
``ikaros.Network``'s ``record`` and ``run(record=...)``, above both, call in here).

The names below are imported when first used, so that the ``ikaros`` command starts fast."""
import importlib

_WHERE = {"open_recording": "reading", "Recorder": "recording", "sweep": "sweeps",
          "plot_signals": "plotting", "plot_raster": "plotting", "plot_images": "plotting",
          "replay_network": "replay"}

__all__ = list(_WHERE)


def __getattr__(name: str):
    if name in _WHERE:
        return getattr(importlib.import_module(f".{_WHERE[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
