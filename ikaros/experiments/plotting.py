"""Plots of recorded signals (matplotlib): signals over time, spike rasters, image grids.

Each takes a Dataset from ``ikaros.open_recording`` or ``net.run(record=...)`` and returns
the matplotlib Axes (or Figure) it drew on, for further styling."""
from __future__ import annotations

import numpy as np


def _pyplot():
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        raise ImportError("plotting needs matplotlib: pip install 'ikaros[notebook]'") \
            from None
    return plt


def _flat(ds, name: str) -> np.ndarray:
    if name not in ds:
        raise KeyError(f'no signal "{name}" in the recording (it has {", ".join(ds)})')
    values = ds[name].values
    return values.reshape(values.shape[0], -1)


def plot_signals(ds, names: list[str] | str | None = None, ax=None, x: str = "tick",
                 title: str | None = None):
    """Each signal over time (every element a line labelled ``NAME[i]``, or ``NAME`` for a
    one-element signal); ``x`` is "tick" or "time" (seconds). All signals when ``names``
    is None."""
    plt = _pyplot()
    names = list(ds.data_vars) if names is None else [names] if isinstance(names, str) \
        else list(names)
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3))
    along = ds[x].values
    for name in names:
        values = _flat(ds, name)
        for i in range(values.shape[1]):
            ax.plot(along, values[:, i], label=name if values.shape[1] == 1 else f"{name}[{i}]")
    ax.set_xlabel("tick" if x == "tick" else "time (s)")
    if title:
        ax.set_title(title)
    if sum(_flat(ds, n).shape[1] for n in names) <= 12:
        ax.legend(loc="best", fontsize="small")
    return ax


def plot_raster(ds, name: str, threshold: float = 0.5, ax=None, title: str | None = None):
    """A spike raster: a dot at (tick, element) wherever the signal is above ``threshold``
    (elements numbered in row-major order)."""
    plt = _pyplot()
    values = _flat(ds, name)
    rows, elements = np.nonzero(values > threshold)
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3))
    ax.scatter(ds["tick"].values[rows], elements, s=4, marker="|", color="black")
    ax.set_xlabel("tick")
    ax.set_ylabel("element")
    ax.set_ylim(-0.5, values.shape[1] - 0.5)
    ax.set_title(title or name)
    return ax


def plot_images(ds, name: str, ticks: list[int] | None = None, count: int = 8,
                columns: int = 4, cmap: str = "gray", vmin: float | None = None,
                vmax: float | None = None):
    """An image signal (rows x columns, or rows x columns x 3 for RGB) at some ticks, as a
    grid of images titled with their tick: the ``ticks`` given, or ``count`` ticks evenly
    spread over the recording. Returns the Figure."""
    plt = _pyplot()
    if name not in ds:
        raise KeyError(f'no signal "{name}" in the recording (it has {", ".join(ds)})')
    signal = ds[name]
    if signal.ndim not in (3, 4):
        raise ValueError(f'"{name}" is not an image sequence (its frames have '
                         f'{signal.ndim - 1} axes)')
    recorded = list(ds["tick"].values)
    if ticks is None:
        positions = np.unique(np.linspace(0, len(recorded) - 1, min(count, len(recorded)))
                              .round().astype(int))
    else:
        missing = [t for t in ticks if t not in recorded]
        if missing:
            raise ValueError(f"ticks {missing} are not in the recording")
        positions = [recorded.index(t) for t in ticks]
    columns = max(1, min(columns, len(positions)))
    rows = -(-len(positions) // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(2.2 * columns, 2.2 * rows),
                             squeeze=False)
    values = signal.values
    low = float(values.min()) if vmin is None else vmin
    high = float(values.max()) if vmax is None else vmax
    for ax in axes.ravel():
        ax.axis("off")
    for ax, k in zip(axes.ravel(), positions):
        ax.imshow(values[k], cmap=cmap, vmin=low, vmax=high)
        ax.set_title(f"tick {recorded[k]}", fontsize="small")
    return fig
