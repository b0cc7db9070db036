"""The checks of a parameter's value against its class's declaration: finite, in range."""
from __future__ import annotations

import math

import numpy as np

from ..description import ParameterSpec
from ..language.values import ValueError_, format_number

_NUMERIC = ("number", "int", "array", "matrix")


def check_parameter(value, spec: ParameterSpec) -> None:
    """Refuse nan and infinite values (unless the spec says ``finite=False``) and values
    outside the spec's range. Raises ValueError_ with the reason."""
    if spec.type not in _NUMERIC:
        return
    if isinstance(value, np.ndarray):
        if value.size == 0:
            return
        if spec.finite and not np.isfinite(value).all():
            raise ValueError_(f"{_bad_element(value)} is not a finite number")
        low, high = (float(value.min()), float(value.max())) if spec.range else (0, 0)
    else:
        number = float(value)
        if spec.finite and not math.isfinite(number):
            raise ValueError_(f"{_text(number)} is not a finite number")
        low = high = number
    if spec.range:
        lowest, highest = spec.range
        if lowest is not None and low < lowest or highest is not None and high > highest:
            raise ValueError_(f"{_text(low if lowest is not None and low < lowest else high)} "
                              f"is outside the range {_range_text(spec.range)}")


def _bad_element(value: np.ndarray) -> str:
    return _text(float(value.reshape(-1)[~np.isfinite(value.reshape(-1))][0]))


def _text(number: float) -> str:
    return str(number) if not math.isfinite(number) else format_number(number)


def _range_text(bounds: tuple) -> str:
    lowest, highest = bounds
    return (f"{'-inf' if lowest is None else format_number(lowest)} to "
            f"{'inf' if highest is None else format_number(highest)}")
