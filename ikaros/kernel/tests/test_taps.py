"""Output taps (kernel/taps.py): the rows a tap keeps hold the values after the tick the keep
followed, whether the compiled tick copies them or NumPy does."""
import numpy as np
import pytest

from ikaros.experiments.signals import select_outputs
from ikaros.testing import load_body

pytest.importorskip("numba", reason="the compiled tick needs numba (pip install ikaros[fast])")

# Counter.OUTPUT is k + 1 after tick k; Double (behind a delay-1 connection, so the compiled
# tick has its gather call) 2 k
BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Scale" name="Double" factor="2"/>
<connection source="Counter.OUTPUT" target="Double.INPUT"/>
"""


def tap_of(net):
    """A tap of Counter.OUTPUT and Double.OUTPUT into 4 rows of -1."""
    _, index = select_outputs(net, ["Counter.OUTPUT", "Double.OUTPUT"])
    return net.add_tap(index, np.full((4, 2), -1, np.float32))


@pytest.mark.parametrize("compiled", ["yes", "no"])
def test_a_kept_row_holds_the_values_after_the_tick_it_follows(tmp_path, compiled):
    net = load_body(tmp_path, BODY, compiled=compiled)
    tap = tap_of(net)
    assert tap.compiled == (compiled == "yes")
    net.step()                       # tick 0
    tap.keep(2)
    net.step()                       # tick 1: the compiled call copies before it runs
    net.step()
    np.testing.assert_array_equal(tap.rows[2], [1, 0])
    tap.keep(0)
    tap.settle()                     # now, not at the next tick
    np.testing.assert_array_equal(tap.rows[0], [3, 4])
    tap.settle()                     # nothing left to copy
    net.step()
    np.testing.assert_array_equal(tap.rows[0], [3, 4])
    np.testing.assert_array_equal(tap.rows[[1, 3]], -1)
    net.close()


def test_a_removed_tap_copies_its_last_row_and_no_more(tmp_path):
    net = load_body(tmp_path, BODY, compiled="yes")
    tap = tap_of(net)
    net.run(ticks=5)
    tap.keep(1)
    net.remove_tap(tap)
    assert not tap.compiled
    np.testing.assert_array_equal(tap.rows[1], [5, 8])
    net.run(ticks=2)
    np.testing.assert_array_equal(tap.rows[[0, 2, 3]], -1)
    net.close()


def test_a_second_tap_copies_with_numpy(tmp_path):
    net = load_body(tmp_path, BODY, compiled="yes")
    first, second = tap_of(net), tap_of(net)
    assert first.compiled and not second.compiled
    net.step()
    first.keep(0)
    second.keep(0)
    net.step()
    np.testing.assert_array_equal(first.rows[0], second.rows[0])
    net.remove_tap(first)            # the second one now goes into the compiled call
    assert second.compiled
    second.keep(3)
    net.step()
    np.testing.assert_array_equal(second.rows[3], [2, 2])
    net.close()


def test_a_tap_moves_into_the_compiled_tick_made_while_running(tmp_path):
    # compiled="auto" makes the compiled tick in the background (at least 64 modules)
    body = BODY + "".join(
        f'<module class="Scale" name="S{k}" factor="1"/>'
        f'<connection source="Double.OUTPUT" target="S{k}.INPUT"/>' for k in range(70))
    net = load_body(tmp_path, body, compiled="auto")
    tap = tap_of(net)
    assert not tap.compiled
    net.step()
    tap.keep(0)                      # copied at once
    assert net.wait_compiled(timeout=120) > 64
    net.step()                       # the compiled tick is taken before this tick
    assert tap.compiled
    tap.keep(1)
    net.step()
    np.testing.assert_array_equal(tap.rows[:2], [[1, 0], [2, 2]])
    net.close()
