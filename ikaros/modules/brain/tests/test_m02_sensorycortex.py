"""Tests of M02_SensoryCortex."""
import numpy as np

from ikaros.testing import load_body as load


def test_passes_the_input_on(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" outputsize="3" min="0" max="2" '
               'step="0.5"/><module class="M02_SensoryCortex" name="C"/>'
               '<connection source="S.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        for _ in range(6):
            net.step()
            assert np.array_equal(net.output("C.OUTPUT"), net.output("S.OUTPUT"))
        assert net.output("C.OUTPUT").shape == (3,)
    finally:
        net.close()
