"""Tests of the Softmax module. Ikaros 2 reads an exponent that its class file never declares
(it declares "exponenet"), so with none set every element is 1/n (golden-v2 Softmax)."""
import numpy as np

from ikaros.module import WARNING
from ikaros.testing import load_body as load

RANDOM = ('<module class="Randomizer" name="R" outputsize_x="3" outputsize_y="2" min="-2" '
          'max="3" seed="5"/>\n<connection source="R.OUTPUT" target="S.INPUT" delay="0"/>\n')


def test_ikaros_2_default_gives_every_element_1_over_n(tmp_path):
    with load(tmp_path, RANDOM + '<module class="Softmax" name="S"/>', dialect="2") as net:
        net.step()
        assert np.allclose(net.output("S.OUTPUT"), np.full((2, 3), 1 / 6))


def test_polynomial_exponent_2(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="Softmax" name="S" exponent="2"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            y = net.output("S.OUTPUT")
            assert y.shape == (2, 3)
            assert np.allclose(y, x ** 2 / np.sum(x ** 2), atol=1e-6)
            assert np.isclose(y.sum(), 1, atol=1e-5)
    finally:
        net.close()


def test_exponential(tmp_path):
    net = load(tmp_path, RANDOM + '<module class="Softmax" name="S" type="exponential"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            assert np.allclose(net.output("S.OUTPUT"), np.exp(x) / np.exp(x).sum(), atol=1e-6)
    finally:
        net.close()


def test_exponential_of_large_values_does_not_overflow(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1000 1000 999"/>\n'
                         '<module class="Softmax" name="S" type="exponential"/>\n'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.step()
        e = np.exp([0, 0, -1])
        assert np.allclose(net.output("S.OUTPUT"), e / e.sum())
    finally:
        net.close()


def test_exponent_and_the_misspelt_ikaros2_name(tmp_path):
    body = ('<module class="Constant" name="C" data="1 -2 3"/>\n'
            '<module class="Softmax" name="A" exponent="1"/>\n'
            '<module class="Softmax" name="B" exponenet="3"/>\n'
            '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="B.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        assert np.allclose(net.output("A.OUTPUT"), np.array([1, 2, 3]) / 6)
        assert np.allclose(net.output("B.OUTPUT"), np.full(3, 1 / 3))    # not used
        assert sum("exponenet" in entry[3] for entry in net.log) == 1
    finally:
        net.close()


def test_zero_sum_gives_zero_and_one_warning(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 0 0 0"/>\n'
                         '<module class="Softmax" name="S" exponent="2"/>\n'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("S.OUTPUT"), np.zeros(4))
        warnings = [m for (_, level, where, m) in net.log if where == "S" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()


def test_nan_or_inf_input_gives_zeros_and_one_warning(tmp_path, capfd):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 nan inf"/>'
                         '<module class="Softmax" name="S" exponent="2"/>'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert net.output("S.OUTPUT").tolist() == [0, 0, 0]
        assert net.output("C.OUTPUT")[0] == 1          # the input is not changed
        assert sum(e[1] == WARNING for e in net.log) == 1
        assert "RuntimeWarning" not in capfd.readouterr().err
    finally:
        net.close()


def test_ikaros_3_default_exponent_is_2(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1, -2, 3"/>'
                         '<module class="Softmax" name="S"/>'
                         '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>',
               dialect="3")
    with net:
        net.step()
        assert np.allclose(net.output("S.OUTPUT"), np.array([1, 4, 9]) / 14)
