"""Experiments: recording runs into HDF5, reading them as xarray Datasets, replay, progress
and parameter sweeps. Depends on the kernel only (the kernel does not import it)."""
from .plotting import plot_images, plot_raster, plot_signals
from .reading import open_recording
from .recording import Recorder
from .sweep import sweep

__all__ = ["open_recording", "Recorder", "sweep", "plot_signals", "plot_raster",
           "plot_images"]
