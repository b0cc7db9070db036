"""Tests of the Median module (Ikaros 3, MODULES-V3 §5)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


@pytest.mark.parametrize("data", ["3 1; 4 2", "5 -1 9 0 2", "7", "1.5 1.5 -3 8 0.25 6"])
def test_median_of_all_elements(tmp_path, data):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         '<module class="Median" name="M"/>'
                         '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.step()
        out = net.output("M.OUTPUT")
        values = np.array(data.replace(";", " ").split(), float)
        assert out.shape == (1,)
        assert out[0] == pytest.approx(np.median(values))
    finally:
        net.close()
