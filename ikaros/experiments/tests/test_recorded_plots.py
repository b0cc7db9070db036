"""The plotting helpers draw exactly the recorded values."""
import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
pytest.importorskip("xarray")

from ikaros.experiments import plot_images, plot_raster, plot_signals  # noqa: E402
from ikaros.experiments.reading import to_dataset  # noqa: E402
from ikaros.experiments.signals import Signal  # noqa: E402


def dataset():
    """Ticks 10..15: A (1 element) = tick, B (2) = (tick, -tick), S (3) spikes, I 2x2 images."""
    ticks = np.arange(10, 16)
    spikes = np.zeros((6, 3), np.float32)
    spikes[[0, 2, 5], [1, 0, 2]] = 1
    images = (ticks[:, None, None] * np.array([[1, 2], [3, 4]])).reshape(6, 4)
    rows = np.concatenate([ticks[:, None], ticks[:, None], -ticks[:, None], spikes, images],
                          axis=1).astype(np.float32)
    signals = [Signal("A", (1,), 0, 1), Signal("B", (2,), 1, 3), Signal("S", (3,), 3, 6),
               Signal("I", (2, 2), 6, 10)]
    return to_dataset(signals, rows, ticks, ticks * 0.01, {})


def test_signals_over_time():
    ax = plot_signals(dataset(), ["A", "B"], x="time")
    lines = ax.get_lines()
    assert [line.get_label() for line in lines] == ["A", "B[0]", "B[1]"]
    np.testing.assert_allclose(lines[0].get_xdata(), np.arange(10, 16) * 0.01)
    np.testing.assert_array_equal(lines[2].get_ydata(), -np.arange(10, 16))
    assert ax.get_xlabel() == "time (s)"


def test_a_spike_raster():
    ax = plot_raster(dataset(), "S")
    points = ax.collections[0].get_offsets()
    np.testing.assert_array_equal(np.asarray(points), [[10, 1], [12, 0], [15, 2]])


def test_an_image_grid():
    fig = plot_images(dataset(), "I", ticks=[11, 14], columns=2)
    shown = [ax for ax in fig.axes if ax.images]
    assert [ax.get_title() for ax in shown] == ["tick 11", "tick 14"]
    np.testing.assert_array_equal(shown[1].images[0].get_array(), [[14, 28], [42, 56]])
    with pytest.raises(ValueError, match="not an image sequence"):
        plot_images(dataset(), "B")
    with pytest.raises(KeyError, match='no signal "X"'):
        plot_signals(dataset(), "X")
