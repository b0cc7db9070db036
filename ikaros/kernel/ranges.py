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
        if lowest is not None and low < lowest:
            raise ValueError_(f"{_text(low)} is below minimum {format_number(lowest)}")
        if highest is not None and high > highest:
            raise ValueError_(f"{_text(high)} is above maximum {format_number(highest)}")


def _bad_element(value: np.ndarray) -> str:
    return _text(float(value.reshape(-1)[~np.isfinite(value.reshape(-1))][0]))


def _text(number: float) -> str:
    return str(number) if not math.isfinite(number) else format_number(number)




def fit_shape(value: np.ndarray, shape: tuple) -> np.ndarray:
    """A matrix parameter's value given the fixed shape its class declares (Ikaros 3
    ``shape``): its elements in row-major order, the missing ones zero. More elements than
    the shape holds raise ValueError_."""
    flat = np.asarray(value, dtype=np.float32).reshape(-1)
    room = int(np.prod(shape)) if shape else 1
    if flat.size > room:
        raise ValueError_(f"Matrix parameter value has {flat.size} elements but shape "
                          f"{','.join(map(str, shape))} only allows {room}")
    fitted = np.zeros(room, dtype=np.float32)
    fitted[:flat.size] = flat
    return fitted.reshape(shape)
