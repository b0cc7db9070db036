"""The example notebook runs top to bottom, and what it prints is what the model does."""
import os
import re

import numpy as np
import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
pytest.importorskip("matplotlib")
pytest.importorskip("h5py")
pytest.importorskip("xarray")

import ikaros  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
NOTEBOOK = os.path.join(ROOT, "examples", "notebooks", "planar_arm_learning.ipynb")
MODEL = os.path.join(ROOT, "examples", "planar_arm_reaching.ikg")
TICKS = 3000


def test_the_planar_arm_notebook_runs_and_shows_the_learning_curve(tmp_path):
    nb = nbformat.read(NOTEBOOK, as_version=4)
    parameters = next(c for c in nb.cells if "parameters" in c.metadata.get("tags", []))
    recording = tmp_path / "reaching.h5"
    parameters.source = f"model = {MODEL!r}\nrecording = {str(recording)!r}\nticks = {TICKS}"
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    env.pop("MPLBACKEND", None)           # the kernel's inline backend makes the figures
    client = nbclient.NotebookClient(nb, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute(env=env)

    text = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code"
                   for o in c.outputs if o.output_type == "stream")
    images = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs
              if "image/png" in o.get("data", {})]
    assert len(images) == 2

    # the same run, in memory, computed here
    net = ikaros.load(MODEL, quiet=True)
    ds = net.run(ticks=TICKS, record=["Arm.DISTANCE", "Babbling.OUTPUT"])
    net.close()
    distance = ds["Arm.DISTANCE"].values[:, 0]
    babbling = ds["Babbling.OUTPUT"].values[:, 0] > 0.5
    assert babbling.sum() == 2000
    assert f"mean distance while babbling: {distance[babbling].mean():.4f}" in text
    assert f"mean distance while reaching: {distance[~babbling].mean():.4f}" in text
    assert distance[~babbling].mean() < 0.02 < 0.2 < distance[babbling].mean()
    assert re.search(r"ticks: 3000 seeds: \{'Shoulder.seed': '1', 'Bend.seed': '2', "
                     r"'Arm.seed': '1'\}", text)
    recorded = ikaros.open_recording(str(recording))
    np.testing.assert_array_equal(recorded["Arm.DISTANCE"].values[:, 0], distance)


def test_the_notebooks_default_recording_is_outside_the_repository():
    """Issue 27, item 5: the parameters cell as shipped writes its recording into a new
    temporary folder, never beside the notebook (run from its folder, as Jupyter does)."""
    nb = nbformat.read(NOTEBOOK, as_version=4)
    parameters = next(c for c in nb.cells if "parameters" in c.metadata.get("tags", []))
    here = os.getcwd()
    os.chdir(os.path.dirname(NOTEBOOK))
    try:
        names: dict = {}
        exec(parameters.source, names)
        recording = os.path.abspath(names["recording"])
        model = os.path.abspath(names["model"])
    finally:
        os.chdir(here)
    assert model == MODEL
    assert not recording.startswith(ROOT + os.sep), recording
    assert os.path.isdir(os.path.dirname(recording)) and not os.path.exists(recording)
    os.rmdir(os.path.dirname(recording))
