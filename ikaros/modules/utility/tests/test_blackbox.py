"""Tests of the BlackBox module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_named_ports_and_zero_outputs_shaped_like_the_first_input(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
               '<module class="BlackBox" name="B" ins="Vision;Goal" outs="Motor; Gaze"/>\n'
               '<module class="Abs" name="A"/>\n'
               '<connection source="C.OUTPUT" target="B.Vision" delay="0"/>\n'
               '<connection source="B.Motor" target="A.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        for name in ("Motor", "Gaze"):
            out = net.output(f"B.{name}")
            assert out.shape == (2, 2) and not out.any()
        assert np.array_equal(net.output("A.OUTPUT"), np.zeros((2, 2)))
    finally:
        net.close()


def test_without_inputs_outputs_have_one_element(tmp_path):
    net = load(tmp_path, '<module class="BlackBox" name="B" outs="X"/>')
    try:
        net.step()
        assert net.output("B.X").shape == (1,) and net.output("B.X")[0] == 0
    finally:
        net.close()


def test_no_ports_at_all(tmp_path):
    net = load(tmp_path, '<module class="BlackBox" name="B" ins="None" debug="yes"/>')
    try:
        net.run(ticks=2)
        assert net.tick == 2
    finally:
        net.close()


def test_debug_prints_the_inputs(tmp_path, capsys):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="5 6"/>\n'
               '<module class="BlackBox" name="B" ins="IN;OTHER" debug="yes"/>\n'
               '<connection source="C.OUTPUT" target="B.IN" delay="0"/>')
    try:
        net.step()
        out = capsys.readouterr().out
        assert "IN: 5 6" in out and "OTHER: unconnected" in out
    finally:
        net.close()


def test_reserved_port_name_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="BlackBox" name="B" outs="tick"/>')
