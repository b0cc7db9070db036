"""Output taps (kernel/taps.py): a tap keeps the values after every due tick in successive rows
of the room it is given, with the tick numbers, and calls back when the room is full or when
asked, whether the compiled tick takes the rows or NumPy does."""
import numpy as np
import pytest

from ikaros.experiments.signals import select_outputs
from ikaros.kernel.taps import ROW
from ikaros.testing import load_body

pytest.importorskip("numba", reason="the compiled tick needs numba (pip install ikaros[fast])")

# Counter.OUTPUT is k + 1 after tick k; Double (behind a delay-1 connection, so the compiled
# tick has its gather call) 2 k
BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Scale" name="Double" factor="2"/>
<connection source="Counter.OUTPUT" target="Double.INPUT"/>
"""


def tap_of(net, every=1, rows=4):
    """A tap of Counter.OUTPUT and Double.OUTPUT into rows of -1, and the list of the ticks
    its call backs came at."""
    _, index = select_outputs(net, ["Counter.OUTPUT", "Double.OUTPUT"])
    calls = []
    tap = net.add_tap(index, np.full((rows, 2), -1, np.float32), every,
                      lambda: calls.append(net.tick))
    return tap, calls


def values(ticks):
    """Counter.OUTPUT and Double.OUTPUT after each tick of ``ticks``."""
    k = np.asarray(ticks, np.float32)
    return np.stack([k + 1, 2 * np.maximum(k, 0)], axis=1)


@pytest.mark.parametrize("compiled", ["yes", "no"])
def test_rows_hold_the_values_after_every_due_tick_and_a_full_room_calls_back(
        tmp_path, compiled):
    net = load_body(tmp_path, BODY, compiled=compiled)
    net.run(ticks=2)
    tap, calls = tap_of(net, every=2, rows=6)
    assert tap.compiled == (compiled == "yes")
    tap.give(1, 4)                   # rows 1 to 3
    net.run(ticks=5)                 # ticks 2 to 6: 2, 4 and 6 are due, 6 taken by settle
    assert calls == []
    tap.settle()
    np.testing.assert_array_equal(tap.rows[1:4], values([2, 4, 6]))
    np.testing.assert_array_equal(tap.ticks[1:4], [2, 4, 6])
    assert tap.state[ROW] == 4
    net.step()                       # the room is full: a call back when tick 7 starts
    assert calls == [7]               # at the start of tick 7
    tap.give(4, 6)
    net.run(ticks=3)                 # ticks 8 to 10: 8 is kept when tick 9 starts
    np.testing.assert_array_equal(tap.rows[4], values([8])[0])
    np.testing.assert_array_equal(tap.rows[[0, 5]], -1)
    tap.request()
    net.step()
    assert calls == [7, 11]
    net.close()


def test_a_removed_tap_keeps_the_tick_just_done_and_no_more(tmp_path):
    net = load_body(tmp_path, BODY, compiled="yes")
    tap, _ = tap_of(net)
    tap.give(0, 4)
    net.run(ticks=2)
    net.remove_tap(tap)
    assert not tap.compiled
    net.run(ticks=2)
    np.testing.assert_array_equal(tap.rows[:2], values([0, 1]))
    np.testing.assert_array_equal(tap.rows[2:], -1)
    net.close()


def test_a_second_tap_steps_with_numpy(tmp_path):
    net = load_body(tmp_path, BODY, compiled="yes")
    (first, _), (second, _) = tap_of(net), tap_of(net)
    assert first.compiled and not second.compiled
    first.give(0, 4)
    second.give(0, 4)
    net.run(ticks=2)
    net.remove_tap(first)            # the second one now goes into the compiled call
    assert second.compiled
    net.run(ticks=2)
    second.settle()
    np.testing.assert_array_equal(first.rows[:2], values([0, 1]))
    np.testing.assert_array_equal(second.rows, values([0, 1, 2, 3]))
    np.testing.assert_array_equal(second.ticks, [0, 1, 2, 3])
    net.close()


def test_a_tap_moves_into_the_compiled_tick_made_while_running(tmp_path):
    # compiled="auto" makes the compiled tick in the background (at least 64 modules)
    body = BODY + "".join(
        f'<module class="Scale" name="S{k}" factor="1"/>'
        f'<connection source="Double.OUTPUT" target="S{k}.INPUT"/>' for k in range(70))
    net = load_body(tmp_path, body, compiled="auto")
    tap, _ = tap_of(net)
    tap.give(0, 4)
    assert not tap.compiled
    net.step()
    assert net.wait_compiled(timeout=120) > 64
    net.step()                       # the compiled tick is taken before this tick
    assert tap.compiled
    net.step()
    tap.settle()
    np.testing.assert_array_equal(tap.rows[:3], values([0, 1, 2]))
    np.testing.assert_array_equal(tap.ticks[:3], [0, 1, 2])
    net.close()
