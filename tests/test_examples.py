"""Every example model loads, has a view, and runs a few ticks with finite outputs."""
import glob
import os
import shutil

import numpy as np
import pytest

import ikaros

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = sorted(glob.glob(os.path.join(ROOT, "examples", "**", "*.ikg"), recursive=True))


@pytest.mark.parametrize("path", EXAMPLES, ids=[os.path.relpath(p, ROOT) for p in EXAMPLES])
def test_example_runs(path, tmp_path):
    folder = os.path.dirname(path)
    for item in os.listdir(folder):              # run a copy: examples may write files
        if os.path.isfile(os.path.join(folder, item)):
            shutil.copy(os.path.join(folder, item), tmp_path)
    net = ikaros.load(str(tmp_path / os.path.basename(path)))
    try:
        assert net.top.views, "an example needs a view"
        net.run(ticks=5)
        assert net.tick == 5
        for inst in net.schedule:
            for name in inst.module._ik_outputs:
                assert np.all(np.isfinite(net.output(f"{inst.path}.{name}"))), name
    finally:
        net.close()


OUTPUT_CLASSES = ("OutputCSV", "OutputFile", "OutputImage", "OutputJPEG", "OutputPNG",
                  "OutputRawImage", "OutputVideoFile", "OutputAudioFile")


def test_examples_write_files_only_into_their_ignored_output_folder():
    from ikaros.language.reader import read_file
    written = []
    for path in EXAMPLES:
        stack = [read_file(path)]
        while stack:
            node = stack.pop()
            stack.extend(node.elements())
            if node.tag == "module" and node.get("class") in OUTPUT_CLASSES:
                written.append(node.get("filename"))
    assert len(written) == 10
    assert all(name.startswith("output/") for name in written), written
    with open(os.path.join(ROOT, ".gitignore")) as f:
        assert "examples/**/output/" in f.read().split()
