"""Tests of the RingBuffer module."""

import numpy as np

from ikaros.testing import load_body as load

SWEEP = ('<module class="Sweep" name="S" outputsize="2" min="1" max="100" step="1"/>'
         '<connection source="S.OUTPUT" target="R.INPUT" delay="0"/>')


def test_scrolls_newest_last_and_wraps_around(tmp_path):
    net = load(tmp_path, SWEEP + '<module class="RingBuffer" name="R" size="3"/>')
    try:
        assert np.array_equal(net.output("R.OUTPUT"), np.zeros((2, 3)))
        expected = [[0, 0, 2], [0, 2, 3], [2, 3, 4], [3, 4, 5], [4, 5, 6]]
        for row in expected:                    # the sweep gives 2, 3, 4, ... from tick 0
            net.step()
            out = net.output("R.OUTPUT")
            assert out.shape == (2, 3) and out.dtype == np.float32
            assert np.array_equal(out, [row, row])
    finally:
        net.close()


def test_matrix_input_and_buffersize(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="X" outputsize_x="2" outputsize_y="2" '
                         'seed="3"/>'
                         '<module class="RingBuffer" name="R" buffersize="4"/>'
                         '<connection source="X.OUTPUT" target="R.INPUT" delay="0"/>')
    try:
        history = []
        for _ in range(6):
            net.step()
            history.append(net.output("X.OUTPUT").reshape(-1))
            last = history[-4:]
            expected = np.zeros((4, 4), np.float32)
            expected[:, 4 - len(last):] = np.array(last).T
            assert np.array_equal(net.output("R.OUTPUT"), expected)
    finally:
        net.close()


def test_size_one_and_default(tmp_path):
    net = load(tmp_path, SWEEP + '<module class="RingBuffer" name="R" size="1"/>'
                                 '<module class="RingBuffer" name="D"/>'
                                 '<connection source="S.OUTPUT" target="D.INPUT" delay="0"/>')
    try:
        net.run(ticks=2)
        assert np.array_equal(net.output("R.OUTPUT"), [[3], [3]])
        assert net.output("D.OUTPUT").shape == (2, 10)
        assert np.array_equal(net.output("D.OUTPUT")[0], [0] * 8 + [2, 3])
    finally:
        net.close()


def test_reset_command(tmp_path):
    net = load(tmp_path, SWEEP + '<module class="RingBuffer" name="R" size="3"/>')
    try:
        net.run(ticks=3)
        net.command("R", "reset")
        net.step()
        assert np.array_equal(net.output("R.OUTPUT"), [[0, 0, 5], [0, 0, 5]])
    finally:
        net.close()
