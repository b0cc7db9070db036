"""Tests of the Sweep module: Ikaros 2's ramp (golden-v2 Sweep): the step added in float32,
then a value past max wraps to min and one below min to max."""

import numpy as np

from ikaros.testing import load_body as load



def test_wraps_to_min_past_max(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" min="100" max="103" step="1"/>')
    try:
        assert np.array_equal(net.output("S.OUTPUT"), [100])      # written in init
        got = []
        for _ in range(7):
            net.step()
            got.append(float(net.output("S.OUTPUT")[0]))
        assert got == [101, 102, 103, 100, 101, 102, 103]
        assert net.tick == 7
    finally:
        net.close()


def test_default_ramp_reaches_max_then_wraps(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S"/>')
    try:
        out = net.output("S.OUTPUT")
        assert out.shape == (1,) and out.dtype == np.float32 and out[0] == 0
        value, got = np.float32(0), []
        for tick in range(23):
            net.step()
            value = np.float32(value + np.float32(0.1))
            if value > 1:                  # ten steps of 0.1f are 1.0000001: wraps to 0
                value = np.float32(0)
            assert net.output("S.OUTPUT")[0] == value, tick
            got.append(float(value))
        assert got[9] == 0                 # golden-v2 Sweep "defaults": 0 at tick 9
    finally:
        net.close()


def test_all_elements_share_the_value_1d_and_2d(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="A" outputsize="4" min="0" max="2" step="0.5"/>\n'
               '<module class="Sweep" name="B" outputsize_x="3" outputsize_y="2" '
               'min="-1" max="1" step="1"/>')
    try:
        assert net.output("A.OUTPUT").shape == (4,)
        assert net.output("B.OUTPUT").shape == (2, 3)
        net.run(ticks=3)
        assert np.array_equal(net.output("A.OUTPUT"), np.full(4, 1.5, np.float32))
        # B: init -1, then 0, 1, -1
        assert np.array_equal(net.output("B.OUTPUT"), np.full((2, 3), -1, np.float32))
    finally:
        net.close()


def test_negative_step_ramps_down_from_max(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" min="0" max="1" step="-0.5"/>')
    try:
        assert net.output("S.OUTPUT")[0] == 0            # init: min
        got = []
        for _ in range(5):
            net.step()
            got.append(float(net.output("S.OUTPUT")[0]))
        assert got == [1.0, 0.5, 0.0, 1.0, 0.5]          # below min wraps to max
    finally:
        net.close()


def test_delay_one_sees_the_init_value_on_tick_0(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="S" min="0" max="10" step="1"/>\n'
               '<module class="Scale" name="D"/>\n'
               '<connection source="S.OUTPUT" target="D.INPUT"/>')
    try:
        for tick in range(4):
            net.step()
            assert net.output("D.OUTPUT")[0] == tick      # S had tick on tick-1
    finally:
        net.close()
