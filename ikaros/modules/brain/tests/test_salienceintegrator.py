"""Tests of the SalienceIntegrator module (Ikaros 3)."""
import numpy as np

from ikaros.testing import load_body as load


def test_decaying_weighted_sum_of_stacked_maps(tmp_path):
    a, b, c = np.array([[1, 0], [0, 2]]), np.array([[0, 3], [1, 1]]), np.array([[2, 2], [2, 2]])
    net = load(tmp_path, '<module class="Constant" name="A" data="1 0; 0 2"/>'
                         '<module class="Constant" name="B" data="0 3; 1 1"/>'
                         '<module class="Constant" name="C" data="2 2; 2 2"/>'
                         '<module class="SalienceIntegrator" name="S" factors="0.5 -1" '
                         'decay="0.25"/>'
                         '<connection source="A.OUTPUT" target="S.INPUT" delay="0"/>'
                         '<connection source="B.OUTPUT" target="S.INPUT" delay="0"/>'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        out = np.zeros((2, 2))
        for _ in range(4):
            out = 0.25 * out + 0.5 * a - 1 * b + 1 * c     # C has no factor: weight 1
            net.step()
            assert net.output("S.OUTPUT").shape == (2, 2)
            assert np.allclose(net.output("S.OUTPUT"), out)
    finally:
        net.close()
