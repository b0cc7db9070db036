"""The oscillator's wave shapes and its phase, shared by AudioOscillator and AudioSynth."""
from __future__ import annotations

import math

import numpy as np

SHAPES = ("sine", "square", "saw", "triangle", "ramp", "pulse")


def wave(shape: str, phase: np.ndarray, duty: float = 0.5) -> np.ndarray:
    """The wave ``shape`` at phases in [0, 1) (float64), between -1 and 1: sine sin 2πφ;
    square +1 where sin 2πφ > 0, else -1; saw 2φ - 1; triangle 4|φ - 0.5| - 1; ramp 1 - 2φ;
    pulse +1 where φ < duty (clipped to 0..1), else -1."""
    if shape == "sine":
        return np.sin(2 * np.pi * phase)
    if shape == "square":
        return np.where(np.sin(2 * np.pi * phase) > 0, 1.0, -1.0)
    if shape == "saw":
        return 2 * phase - 1
    if shape == "triangle":
        return 4 * np.abs(phase - 0.5) - 1
    if shape == "ramp":
        return 1 - 2 * phase
    if shape == "pulse":
        return np.where(phase < min(max(duty, 0.0), 1.0), 1.0, -1.0)
    raise ValueError(f'unknown wave shape "{shape}" (known: {", ".join(SHAPES)})')


def phases(start: float, steps: np.ndarray, out: np.ndarray) -> float:
    """Write into ``out`` the phase of each sample (starting at ``start``, in [0, 1)) and
    return the phase after the last one: after each sample the phase advances by its step
    and keeps only its fraction (p += step; p -= floor p), one sample after another, as a
    double."""
    p = start
    floor = math.floor
    for i, step in enumerate(steps.tolist()):
        out[i] = p
        p += step
        p -= floor(p)
    return p
