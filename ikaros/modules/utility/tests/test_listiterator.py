"""Tests of the ListIterator module. SYNC_OUT as in Ikaros 2 (golden-v2 ListIterator): 1 on the
first tick and on the tick after a pass ends, except for a list of one entry."""
import numpy as np

from ikaros.testing import load_body as load


def steps(net, n, out="L.OUTPUT"):
    got, sync = [], []
    for _ in range(n):
        net.step()
        got.append(net.output(out).tolist())
        sync.append(float(net.output("L.SYNC_OUT")[0]))
    return got, sync


def test_rows_with_repeat_and_sync_out(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="One" data="1"/>'
               '<module class="ListIterator" name="L" listdata="0 1 2; 3 4 5" repeat="yes"/>'
               '<connection source="One.OUTPUT" target="L.SYNC_IN" delay="0"/>')
    try:
        assert np.array_equal(net.output("L.OUTPUT"), [0, 0, 0])
        got, sync = steps(net, 5)
        assert got == [[0, 1, 2], [3, 4, 5], [0, 1, 2], [3, 4, 5], [0, 1, 2]]
        assert sync == [1, 0, 1, 0, 1]
    finally:
        net.close()


def test_single_row_steps_elements_and_stops_without_repeat(tmp_path):
    net = load(tmp_path, '<module class="ListIterator" name="L" listdata="7 8 9"/>')
    try:
        assert net.output("L.OUTPUT").shape == (1,)
        got, sync = steps(net, 5)                  # SYNC_IN unconnected: every tick
        assert got == [[7], [8], [9], [9], [9]]
        assert sync == [1, 0, 0, 1, 0]             # once more after the last pass
    finally:
        net.close()


def test_steps_only_when_sync_in_is_set(tmp_path):
    net = load(tmp_path, '<module class="Sweep" name="S" min="0" max="1" step="1"/>'
               '<module class="ListIterator" name="L" listdata="1 2 3" repeat="true"/>'
               '<connection source="S.OUTPUT" target="L.SYNC_IN" delay="0"/>')
    try:
        got, sync = steps(net, 8)                  # S: 1, 0, 1, 0, ...
        assert got == [[1], [1], [2], [2], [3], [3], [1], [1]]
        assert sync == [1, 0, 0, 0, 0, 1, 0, 0]    # the tick after the pass ended
    finally:
        net.close()


def test_input_overrides_listdata(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; 3 4; 5 6"/>'
               '<module class="ListIterator" name="L" listdata="0" repeat="yes"/>'
               '<connection source="C.OUTPUT" target="L.INPUT" delay="0"/>')
    try:
        got, _ = steps(net, 4)
        assert got == [[1, 2], [3, 4], [5, 6], [1, 2]]
        net.set_parameter("C.data", "10 20; 30 40; 50 60")    # the list may change
        got, sync = steps(net, 2)
        assert got == [[30, 40], [50, 60]]
        assert sync == [0, 0]
    finally:
        net.close()


def test_column_list_and_single_entry(tmp_path):
    net = load(tmp_path, '<module class="ListIterator" name="L" listdata="4; 5" repeat="1"/>'
               '<module class="ListIterator" name="M" listdata="6" repeat="1"/>')
    try:
        got, sync = steps(net, 3)
        assert got == [[4], [5], [4]]
        assert sync == [1, 0, 1]
        net.step()
        assert np.array_equal(net.output("M.OUTPUT"), [6])
        assert np.array_equal(net.output("M.SYNC_OUT"), [0])       # one entry: first tick only
    finally:
        net.close()
