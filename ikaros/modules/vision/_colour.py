"""Colour modules take the three planes of an image either as one colour image (INPUT:
(3, rows, cols), docs/images.md) or as three gray images (INPUT0..2, as in Ikaros 2).
Helpers for that, and the base class of the modules that also give three planes back."""
from __future__ import annotations

import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import as_image, image_shape, is_colour


def plane_inputs_shape(module: Module, prefix: str = "INPUT",
                       optional: bool = False) -> tuple | None:
    """The (rows, cols) of the planes connected to ``prefix`` (a colour image) or to
    ``prefix``0..2 (a vector is a one-row plane); None while unknown, or when nothing is
    connected and ``optional``. ValueError for a wrong mix of connections or shapes."""
    names = [f"{prefix}{i}" for i in range(3)]
    separate = [module.connected(n) for n in names]
    whole = module.connected(prefix)
    if optional and not whole and not any(separate):
        return None
    if whole == any(separate) or (any(separate) and not all(separate)):
        raise ValueError(f"connect either {prefix} (a colour image) or all three of "
                         f"{', '.join(names[:2])} and {names[2]}")
    if whole:
        shape = module.input_shape(prefix)
        if shape and not is_colour(shape):
            raise ValueError(f"{prefix} must be a colour image (3, rows, cols), not {shape}")
        return shape[1:] if shape else None
    shapes = [module.input_shape(n) for n in names]
    if not all(shapes):
        return None
    shapes = [image_shape(shape, name, gray=True) for name, shape in zip(names, shapes)]
    if len(set(shapes)) > 1:
        raise ValueError(f"{', '.join(names)} must have the same size, not "
                         f"{', '.join(map(str, shapes))}")
    return shapes[0]


def plane_inputs(module: Module, prefix: str = "INPUT") -> list[np.ndarray] | None:
    """The three planes (views) given on ``prefix`` or ``prefix``0..2, or None."""
    whole = getattr(module, prefix)
    if whole is not None:
        return list(whole)
    planes = [getattr(module, f"{prefix}{i}") for i in range(3)]
    return None if planes[0] is None else [as_image(p) for p in planes]


class ThreePlanes(Module):
    """Reads three planes from INPUT or from INPUT0, INPUT1 and INPUT2 (``self.planes_in``)
    and writes OUTPUT, whose planes are OUTPUT0, OUTPUT1 and OUTPUT2 (views of the same
    memory, so nothing is copied)."""

    INPUT = Input("a colour image (3, rows, cols); or connect INPUT0, INPUT1 and INPUT2",
                  optional=True)
    INPUT0 = Input("the first plane (rows, cols), when INPUT is not connected",
                   optional=True)
    INPUT1 = Input("the second plane (rows, cols)", optional=True)
    INPUT2 = Input("the third plane (rows, cols)", optional=True)
    OUTPUT = Output("the result as one image (3, rows, cols)")
    OUTPUT0 = Output("the first plane of OUTPUT", alias="OUTPUT[0]")
    OUTPUT1 = Output("the second plane of OUTPUT", alias="OUTPUT[1]")
    OUTPUT2 = Output("the third plane of OUTPUT", alias="OUTPUT[2]")

    def set_sizes(self):
        shape = plane_inputs_shape(self)
        if shape:
            self.set_output_shape("OUTPUT", (3,) + shape)

    def init(self):
        self.planes_in = plane_inputs(self)
