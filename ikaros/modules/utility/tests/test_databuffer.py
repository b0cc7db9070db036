"""Tests of the DataBuffer module. Ikaros 2 replaces row rand() % size whatever the policy
(golden-v2 DataBuffer), with glibc's rand() unseeded: 1804289383, 846930886, 1681692777,
1714636915, 1957747793, 424238335, 719885386, 1649760492, 596516649, 1189641421 (the C
library's documented sequence for seed 1)."""
import numpy as np

from ikaros.testing import load_body as load

# Sweep from 1 by 1 with delay 0: the input is k + 2 (in both elements) on tick k.
BODY = ('<module class="Sweep" name="S" min="1" max="100" step="1" outputsize="2"/>\n'
        '<module class="DataBuffer" name="B" size="3" {attrs}/>\n'
        '<connection source="S.OUTPUT" target="B.INPUT" delay="0"/>')


GLIBC_SEED_1 = [1804289383, 846930886, 1681692777, 1714636915, 1957747793, 424238335,
                719885386, 1649760492, 596516649, 1189641421]


def test_every_policy_replaces_row_rand_mod_size_as_ikaros_2(tmp_path):
    for policy in ("random", "circular", "queue"):
        folder = tmp_path / policy
        folder.mkdir()
        with load(folder, BODY.format(attrs=f'update_policy="{policy}"')) as net:
            rows = np.zeros(3)
            for k, r in enumerate(GLIBC_SEED_1):
                net.step()
                rows[r % 3] = k + 2
                assert np.array_equal(net.output("B.OUTPUT")[:, 0], rows), (policy, k)


def test_queue_puts_the_newest_first(tmp_path):
    net = load(tmp_path, BODY.format(attrs='update_policy="queue" honour_policy="yes"'))
    try:
        assert net.output("B.OUTPUT").shape == (3, 2)
        history = []
        for k in range(6):
            net.step()
            history.insert(0, k + 2)
            expected = (history + [0, 0, 0])[:3]
            assert np.array_equal(net.output("B.OUTPUT"), np.repeat(
                np.array(expected, np.float32)[:, None], 2, axis=1)), k
    finally:
        net.close()


def test_circular_writes_rows_in_turn(tmp_path):
    net = load(tmp_path, BODY.format(attrs='update_policy="circular" honour_policy="yes"'))
    try:
        rows = np.zeros(3)
        for k in range(7):
            net.step()
            rows[k % 3] = k + 2
            assert np.array_equal(net.output("B.OUTPUT")[:, 0], rows), k
            assert np.array_equal(net.output("B.OUTPUT")[:, 1], rows)
    finally:
        net.close()


def test_random_replaces_one_row_per_tick_and_is_repeatable(tmp_path):
    def run(folder):
        net = load(folder, BODY.format(attrs='update_policy="random" seed="7"'))
        try:
            frames = []
            previous = net.output("B.OUTPUT").copy()
            for k in range(10):
                net.step()
                out = net.output("B.OUTPUT").copy()
                changed = np.any(out != previous, axis=1)
                assert changed.sum() == 1                   # one row, the new input
                assert np.all(out[changed] == k + 2)
                previous = out
                frames.append(out)
            return frames
        finally:
            net.close()
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    first, second = run(tmp_path / "a"), run(tmp_path / "b")
    assert all(np.array_equal(a, b) for a, b in zip(first, second))


def test_matrix_input_is_stored_flat(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
               '<module class="DataBuffer" name="B" size="2" update_policy="queue" '
               'honour_policy="yes"/>\n'
               '<connection source="C.OUTPUT" target="B.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("B.OUTPUT"), [[1, 2, 3, 4], [0, 0, 0, 0]])
        net.step()
        assert np.array_equal(net.output("B.OUTPUT"), [[1, 2, 3, 4], [1, 2, 3, 4]])
    finally:
        net.close()
