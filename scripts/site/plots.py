"""The documentation site's plots (matplotlib, written as SVG without dates so that a
rebuild gives the same files)."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

plt.rcParams.update({"svg.fonttype": "none", "font.size": 9, "axes.spines.top": False,
                     "axes.spines.right": False, "svg.hashsalt": "ikaros"})
LINES = 16          # an output of more elements is drawn as an image of its last tick


def _drawable(rows: np.ndarray) -> str | None:
    """How an output recorded tick by tick is drawn: "lines", "image", "rgb" or None."""
    last = rows[-1]
    if not np.all(np.isfinite(rows)) and not np.any(np.isfinite(rows)):
        return None
    if last.size <= LINES:
        return "lines"
    if last.ndim == 2:
        return "image"
    if last.ndim == 3 and last.shape[0] == 3:
        return "rgb"
    return "lines" if last.ndim == 1 and last.size <= 64 else None


def plot_outputs(outputs: dict[str, np.ndarray], path: str, title: str) -> bool:
    """Draw each output (an array of ticks × the output's shape): small outputs as a line
    per element over the ticks, matrices and colour images as their last tick. False when
    nothing could be drawn."""
    kinds = {name: _drawable(rows) for name, rows in outputs.items()}
    shown = [(name, kind) for name, kind in kinds.items() if kind][:6]
    if not shown:
        return False
    fig, axes = plt.subplots(1, len(shown), figsize=(3.2 * len(shown), 2.4), squeeze=False)
    for ax, (name, kind) in zip(axes[0], shown):
        rows = outputs[name]
        if kind == "lines":
            ticks = np.arange(len(rows))
            ax.plot(ticks, rows.reshape(len(rows), -1), linewidth=1)
            ax.set_xlabel("tick")
        elif kind == "image":
            ax.imshow(rows[-1], cmap="gray", interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
        else:
            rgb = np.clip(np.moveaxis(rows[-1], 0, -1), 0, 1)
            ax.imshow(rgb, interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
        ax.set_title(name, fontsize=9)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, format="svg", metadata={"Date": None})
    plt.close(fig)
    return True


def bar_chart(path: str, title: str, labels: list[str], series: dict[str, list],
              unit: str, log: bool = True) -> None:
    """Horizontal bars: a group per label, a bar per series (None: no figure), on a log
    axis by default (the figures span orders of magnitude)."""
    fig, ax = plt.subplots(figsize=(7, 0.5 + 0.45 * len(labels) * max(1, len(series)) / 1.6))
    height = 0.8 / len(series)
    y = np.arange(len(labels))
    for k, (name, values) in enumerate(series.items()):
        pos = [y[i] + k * height for i, v in enumerate(values) if v is not None]
        ax.barh(pos, [v for v in values if v is not None], height=height, label=name)
        for p, v in zip(pos, (v for v in values if v is not None)):
            ax.annotate(f"{v:g}", (v, p), xytext=(3, 0), textcoords="offset points",
                        va="center", fontsize=7)
    ax.set_yticks(y + height * (len(series) - 1) / 2, labels)
    ax.invert_yaxis()
    if log:
        ax.set_xscale("log")
    ax.set_xlabel(unit)
    ax.set_title(title, fontsize=10)
    if len(series) > 1:
        ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    fig.savefig(path, format="svg", metadata={"Date": None})
    plt.close(fig)
