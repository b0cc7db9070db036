"""Tests of the Concat module."""
import numpy as np

from ikaros.testing import load_body as load


def test_concatenates_connections_in_order(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2"/>\n'
               '<module class="Constant" name="B" data="3 4; 5 6"/>\n'
               '<module class="Sweep" name="S" min="0" max="100" step="1"/>\n'
               '<module class="Concat" name="C"/>\n'
               '<connection source="A.OUTPUT" target="C.INPUT" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="C.INPUT" delay="0"/>\n'
               '<connection source="S.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        for tick in range(3):
            net.step()
            # Ikaros 2: the connection declared last comes first
            assert np.array_equal(net.output("C.OUTPUT"), [tick + 1, 3, 4, 5, 6, 1, 2])
    finally:
        net.close()


def test_concatenation_declared_keeps_the_declaration_order(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2"/>\n'
               '<module class="Constant" name="B" data="3 4; 5 6"/>\n'
               '<module class="Concat" name="C" INPUT.concatenation="declared"/>\n'
               '<connection source="A.OUTPUT" target="C.INPUT" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("C.OUTPUT"), [1, 2, 3, 4, 5, 6])
    finally:
        net.close()


def test_single_connection_keeps_its_shape(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="B" data="3 4; 5 6"/>\n'
               '<module class="Concat" name="C" debug="yes"/>\n'
               '<connection source="B.OUTPUT" target="C.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("C.OUTPUT"), [[3, 4], [5, 6]])
    finally:
        net.close()
