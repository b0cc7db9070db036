"""Tests of the TimeSeries module (Ikaros 3, MODULES-V3 §2)."""
import numpy as np

from ikaros.testing import load_body as load


def _run(tmp_path, attrs, ticks, tick_duration="1"):
    net = load(tmp_path, f'<module class="TimeSeries" name="T" {attrs}/>',
               tick_duration=tick_duration)
    out, trig = [], []
    try:
        for _ in range(ticks):
            net.step()
            out.append(net.output("T.OUTPUT").tolist())
            trig.append(float(net.output("T.TRIG")[0]))
    finally:
        net.close()
    return out, trig


def test_duration_column_and_loop_the_reference_table(tmp_path):
    # MODULES-V3 §2 [oracle]: tick_duration 0.5, data 1,2;3,4;5,6, first_column_duration, loop
    out, trig = _run(tmp_path, 'data="1, 2; 3, 4; 5, 6" first_column_duration="yes" '
                               'loop="yes"', 9, tick_duration="0.5")
    assert out == [[2], [2], [4], [4], [4], [4], [4], [4], [6]]
    assert trig == [0, 1, 0, 0, 0, 0, 0, 1, 0]


def test_without_loop_the_last_row_is_held_without_trig(tmp_path):
    # MODULES-V3 §2: without the duration column and loop, TRIG is 1 on ticks 2 and 4 only
    out, trig = _run(tmp_path, 'data="1, 2; 3, 4; 5, 6" base_duration="2"', 8)
    assert out == [[1, 2], [1, 2], [3, 4], [3, 4], [5, 6], [5, 6], [5, 6], [5, 6]]
    assert trig == [0, 1, 0, 1, 0, 0, 0, 0]


def test_default_data_and_output_size(tmp_path):
    out, trig = _run(tmp_path, 'loop="yes"', 4)
    assert out == [[1, 2, 3], [4, 5, 6], [7, 8, 9], [1, 2, 3]]
    assert trig == [1, 1, 1, 1]
    assert np.shape(out[0]) == (3,)
