"""Tests of the Ones module."""

import numpy as np

from ikaros.testing import load_body as load


def test_default_is_a_single_one(tmp_path):
    net = load(tmp_path, '<module class="Ones" name="O"/>')
    try:
        out = net.output("O.OUTPUT")                   # written in init
        assert out.shape == (1,) and out.dtype == np.float32 and out[0] == 1
        net.step()
        assert np.array_equal(net.output("O.OUTPUT"), [1])
    finally:
        net.close()


def test_sizes_and_value(tmp_path):
    net = load(tmp_path, '<module class="Ones" name="A" size_x="4"/>'
                         '<module class="Ones" name="B" size_x="3" size_y="2" value="-2.5"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("A.OUTPUT"), np.ones(4))
        assert np.array_equal(net.output("B.OUTPUT"), np.full((2, 3), -2.5))
    finally:
        net.close()


def test_value_change_takes_effect(tmp_path):
    net = load(tmp_path, '<module class="Ones" name="O" size_x="2" size_y="2"/>')
    try:
        net.step()
        net.set_parameter("O.value", 7)
        net.step()
        assert np.array_equal(net.output("O.OUTPUT"), np.full((2, 2), 7))
    finally:
        net.close()
