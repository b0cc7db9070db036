"""Tests of the LinearSplines module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_single_function_matches_np_interp(tmp_path):
    points = np.array([[3, 5], [4, 20], [7, 25], [9, 10]])
    text = "; ".join(f"{x} {y}" for x, y in points)
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="10" min="0" '
               'max="12" seed="9"/>'
               f'<module class="LinearSplines" name="L" points="{text}"/>'
               '<connection source="R.OUTPUT" target="L.INPUT" delay="0"/>')
    try:
        for _ in range(5):
            net.step()
            x = net.output("R.OUTPUT")
            assert np.allclose(net.output("L.OUTPUT"),
                               np.interp(x, points[:, 0], points[:, 1]), atol=1e-4)
    finally:
        net.close()


def test_hand_worked_ends_and_segments(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 3 3.5 4 5.5 9 100"/>'
               '<module class="LinearSplines" name="L" points="3 5; 4 20; 7 25; 9 10"/>'
               '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("L.OUTPUT"), [5, 5, 12.5, 20, 22.5, 10, 10])
    finally:
        net.close()


def test_two_functions_cycle_and_padding_is_ignored(tmp_path):
    # function 0: (0,0) (1,10) (2,30) (4,40); function 1: (0,4) (5,0) (10,-1), padded
    points = "0 0 0 4; 1 10 5 0; 2 30 10 -1; 4 40 0 0"
    net = load(tmp_path, '<module class="Constant" name="C" data="1.5 2.5 3 20 -1"/>'
               f'<module class="LinearSplines" name="L" points="{points}"/>'
               '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>')
    try:
        net.step()
        # elements 0, 2, 4 use function 0; elements 1, 3 use function 1
        assert np.allclose(net.output("L.OUTPUT"), [20, 2, 35, -1, 0])
    finally:
        net.close()


def test_a_repeated_x_is_a_jump(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0.5 1 1.5 3"/>'
               '<module class="LinearSplines" name="L" points="0 0; 1 0; 1 1; 2 1"/>'
               '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("L.OUTPUT"), [0, 1, 1, 1])
    finally:
        net.close()


def test_matrix_input_keeps_its_shape(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 1; 2 3"/>'
               '<module class="LinearSplines" name="L" points="0 0 0 0; 3 6 3 -3"/>'
               '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("L.OUTPUT"), [[0, -1], [4, -3]])
    finally:
        net.close()


def test_odd_number_of_columns_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="even number"):
        load(tmp_path, '<module class="Constant" name="C" data="1"/>'
             '<module class="LinearSplines" name="L" points="1 2 3; 4 5 6"/>'
             '<connection source="C.OUTPUT" target="L.INPUT"/>')
