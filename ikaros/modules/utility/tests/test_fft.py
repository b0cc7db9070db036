"""Tests of the FFT module. Ikaros 2 gives bins 0 ... N / 2 and 0 above them (golden-v2 FFT);
bins="all" gives every bin."""
import numpy as np

from ikaros.testing import load_body as load


def test_matches_numpy_fft_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="8" seed="5"/>'
               '<module class="FFT" name="F" bins="all"/>'
               '<module class="FFT" name="H"/>'
               '<connection source="R.OUTPUT" target="F.INPUT" delay="0"/>'
               '<connection source="R.OUTPUT" target="H.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            n = len(x)
            k = np.arange(n)
            # the DFT written out, independent of np.fft
            spectrum = (x[None, :] * np.exp(-2j * np.pi * k[:, None] * k[None, :] / n)).sum(1)
            assert np.allclose(net.output("F.REAL_OUTPUT"), spectrum.real, atol=1e-5)
            assert np.allclose(net.output("F.IM_OUTPUT"), spectrum.imag, atol=1e-5)
            half = np.where(k <= n // 2, spectrum, 0)
            assert np.allclose(net.output("H.REAL_OUTPUT"), half.real, atol=1e-5)
            assert np.allclose(net.output("H.IM_OUTPUT"), half.imag, atol=1e-5)
    finally:
        net.close()


def test_hand_worked_values_and_odd_length(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 0 0 0"/>'
               '<module class="Constant" name="B" data="1 2 3"/>'
               '<module class="FFT" name="FA" bins="all"/><module class="FFT" name="FB" bins="all"/>'
               '<connection source="A.OUTPUT" target="FA.INPUT" delay="0"/>'
               '<connection source="B.OUTPUT" target="FB.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("FA.REAL_OUTPUT"), [1, 1, 1, 1])   # an impulse is flat
        assert np.allclose(net.output("FA.IM_OUTPUT"), [0, 0, 0, 0])
        # 1 2 3: X0 = 6, X1 = -1.5 + 0.866i, X2 = -1.5 - 0.866i
        assert np.allclose(net.output("FB.REAL_OUTPUT"), [6, -1.5, -1.5])
        assert np.allclose(net.output("FB.IM_OUTPUT"), [0, np.sqrt(3) / 2, -np.sqrt(3) / 2],
                           atol=1e-6)
    finally:
        net.close()


def test_matrix_is_transformed_row_by_row(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 1 1 1; 0 1 0 -1"/>'
               '<module class="FFT" name="F" bins="all"/>'
               '<connection source="C.OUTPUT" target="F.INPUT" delay="0"/>')
    try:
        net.step()
        assert net.output("F.REAL_OUTPUT").shape == (2, 4)
        assert np.allclose(net.output("F.REAL_OUTPUT"), [[4, 0, 0, 0], [0, 0, 0, 0]],
                           atol=1e-6)
        assert np.allclose(net.output("F.IM_OUTPUT"), [[0, 0, 0, 0], [0, -2, 0, 2]],
                           atol=1e-6)
    finally:
        net.close()
