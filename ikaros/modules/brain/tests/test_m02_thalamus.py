"""Tests of M02_Thalamus."""
import numpy as np

from ikaros.testing import load_body as load


def test_passes_input_and_outputs_its_maximum(tmp_path):
    (tmp_path / "x.txt").write_text("X/3\n0 0 0\n0.2 0.7 0.1\n-1 -2 -0.5\n1 0 1\n")
    net = load(tmp_path, '<module class="InputFile" name="X" filename="x.txt"/>'
               '<module class="M02_Thalamus" name="T"/>'
               '<connection source="X.X" target="T.INPUT" delay="0"/>')
    try:
        rows = [[0, 0, 0], [0.2, 0.7, 0.1], [-1, -2, -0.5], [1, 0, 1]]
        for row in rows:
            net.step()
            assert np.allclose(net.output("T.OUTPUT"), row)
            assert np.isclose(net.output("T.TH")[0], max(row))
    finally:
        net.close()
