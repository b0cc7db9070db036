"""Experiments: recording runs into HDF5, reading them as xarray Datasets, replay, progress
and parameter sweeps. Depends on the kernel only (the kernel does not import it)."""
from .reading import open_recording
from .recording import Recorder

__all__ = ["open_recording", "Recorder"]
