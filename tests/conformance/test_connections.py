"""DESIGN §3: several connections into one input, flattening, flatten/stack, sub-ranges,
selectors and zero-delay memory sharing."""
import numpy as np
import pytest

import ikaros
from conformance_util import lines_of, load, same, trace, v, x


def test_concatenation_puts_the_last_declared_connection_first():
    # Ikaros 2 (FORMATS §7.1): each new connection goes to the head of the input's list
    net = load("concat.ikg")
    net.step()
    same(net.output("X.INPUT"), [7, 8, 9, 1, 2])
    same(net.output("X.OUTPUT"), [7, 8, 9, 1, 2])


def test_concatenation_declared_keeps_declaration_and_listed_order():
    net = load("concat.ikg", concatenation="declared")
    rows = trace(net, ["X.OUTPUT", "Flat8.OUTPUT", "WinCat.OUTPUT"], 3)
    for n, row in enumerate(rows):
        same(row["X.OUTPUT"], [1, 2, 7, 8, 9])
        same(row["Flat8.OUTPUT"], [1, 2, 3, 4, 5, 6, 1, 2])
        same(row["WinCat.OUTPUT"], [x(n - 1), x(n - 2), 1, 2])


def test_concatenation_in_an_ikaros_3_file_overlays_from_element_0():
    # Ikaros 3 (FORMATS §7.3): each connection writes from element 0, a later one over an
    # earlier one; the input takes the size of the largest
    net = load("concat.ikg", dialect=3)
    net.run(ticks=2)           # the first tick reads zeros over delay 1 in an Ikaros 3 file
    same(net.output("X.INPUT"), [7, 8, 9])
    same(net.output("Four.INPUT"), [7, 8, 9])
    same(net.output("Flat8.INPUT"), [[1, 2], [3, 4], [5, 6]])


def test_a_zero_delay_connection_beside_another_warns_in_an_ikaros_2_file():
    net = load("concat.ikg", quiet=True)
    line = lines_of("concat.ikg", 'target="Mixed.INPUT" delay="0"')[0]
    found = [w for w in net.warnings if "Ikaros 2 refuses" in w.message]
    assert [(w.line, w.element) for w in found] == [(line, "<connection>")]
    assert "Mixed.INPUT is fed over delay 0" in found[0].message
    with pytest.raises(ikaros.ModelError, match=f"concat.ikg:{line}:.*Ikaros 2 refuses"):
        load("concat.ikg", strict=True)
    assert not [w for w in load("concat.ikg", dialect=3, quiet=True).warnings
                if "Ikaros 2 refuses" in w.message]


def test_four_copies_of_a_vector_give_twelve():
    net = load("concat.ikg")
    net.step()
    same(net.output("Four.OUTPUT"), [7, 8, 9] * 4)


def test_flattened_when_any_part_has_rank_two():
    net = load("concat.ikg")
    net.step()
    same(net.output("Flat8.OUTPUT"), [1, 2, 1, 2, 3, 4, 5, 6])


def test_window_among_several_connections_is_laid_end_to_end():
    net = load("concat.ikg")
    for n, row in enumerate(trace(net, ["WinCat.OUTPUT"], 4)):
        same(row["WinCat.OUTPUT"], [1, 2, x(n - 2), x(n - 1)])


def test_single_matrix_connection_keeps_its_shape():
    net = load("concat.ikg")
    net.step()
    same(net.output("Whole.OUTPUT"), [[1, 2], [3, 4], [5, 6]])


def test_concatenation_with_different_delays():
    net = load("concat.ikg")
    rows = trace(net, ["Mixed.OUTPUT"], 3)
    # K2 with delay 0, then M32 with delay 2 (laid first): tick 0 sees 0 for M32 (before
    # its init value), tick 1 sees M32's init value (the value of tick -1).
    same(rows[0]["Mixed.OUTPUT"], [0, 0, 0, 0, 0, 0, 1, 2])
    same(rows[1]["Mixed.OUTPUT"], [1, 2, 3, 4, 5, 6, 1, 2])
    same(rows[2]["Mixed.OUTPUT"], [1, 2, 3, 4, 5, 6, 1, 2])


def test_flatten_input():
    net = load("flatten_stack.ikg")
    net.step()
    same(net.output("F1.OUTPUT"), [1, 2, 3, 4])
    same(net.output("F2.OUTPUT"), [5, 6, 7, 8, 1, 2, 3, 4])     # an Ikaros 2 file: last first
    same(net.output("FRows.OUTPUT"), [7, 8, 1, 2])


def test_flatten_input_in_an_ikaros_3_file_is_in_declaration_order():
    net = load("flatten_stack.ikg", dialect=3)
    net.run(ticks=2)
    same(net.output("F2.OUTPUT"), [1, 2, 3, 4, 5, 6, 7, 8])
    same(net.output("FRows.OUTPUT"), [1, 2, 7, 8])


def test_flatten_input_with_a_window_is_delay_major():
    net = load("flatten_stack.ikg")
    for n, row in enumerate(trace(net, ["FWin.OUTPUT"], 4)):
        same(row["FWin.OUTPUT"], [9, 10, 11] + v(n - 2) + v(n - 1))
    net = load("flatten_stack.ikg", concatenation="declared")
    for n, row in enumerate(trace(net, ["FWin.OUTPUT"], 4)):
        same(row["FWin.OUTPUT"], v(n - 1) + v(n - 2) + [9, 10, 11])


def test_stack_input():
    net = load("flatten_stack.ikg")
    net.step()
    same(net.output("S2.OUTPUT"), [[[1, 2], [3, 4]], [[5, 6], [7, 8]]])
    same(net.output("S1.OUTPUT"), [[[5, 6], [7, 8]]])


def test_sub_ranges_by_offsets():
    net = load("subranges.ikg")
    net.step()
    same(net.output("R.OUTPUT"), [1, 2, 3, 0, 8, 9, 10, 0, 1, 0, 2, 3])
    same(net.output("Y.OUTPUT"), [3, 4, 5])


def test_zero_delay_with_offsets_copies_in_the_same_tick():
    net = load("subranges.ikg")
    for n, row in enumerate(trace(net, ["Z.OUTPUT"], 3)):
        same(row["Z.OUTPUT"], [0, x(n)])


def test_selectors():
    net = load("selectors.ikg")
    net.step()
    same(net.output("P1.OUTPUT"), [[1, 2], [3, 4]])
    same(net.output("P2.OUTPUT"), [1, 2, 3, 4])
    same(net.output("P3.OUTPUT"), [1, 2])
    same(net.output("P4.OUTPUT"), [1, 2, 3, 4])
    same(net.output("P5.OUTPUT"), [1, 2])
    same(net.output("P6.OUTPUT"), [[1, 2], [3, 4]])
    same(net.output("P7.OUTPUT"), [3, 4])
    same(net.output("P8.OUTPUT"), [2, 4])


def test_stepped_selectors_pair_by_cardinality_and_target_range_sets_the_size():
    # target [0:6:2] is the half-open range 0..6 stepping 2 (reference test 205)
    net = load("selectors.ikg")
    net.step()
    same(net.output("Stepped.OUTPUT"), [10, 0, 30, 0, 50, 0])


def test_negative_step_reverses():
    net = load("selectors.ikg")
    net.step()
    same(net.output("Reverse.OUTPUT"), [3, 2, 1])


def test_target_selectors_place_parts_and_size_the_input():
    net = load("selectors.ikg")
    net.step()
    same(net.output("Placed.OUTPUT"), [3, 0, 0, 1, 2])


def test_zero_delay_selector_copies_in_the_same_tick():
    net = load("selectors.ikg")
    for n, row in enumerate(trace(net, ["Zero.OUTPUT"], 3)):
        same(row["Zero.OUTPUT"], [0, x(n)])


def test_single_element_selector_gives_a_connected_one_element_input():
    net = load("selector_single.ikg")
    for n, row in enumerate(trace(net, ["P.OUTPUT", "Q.OUTPUT"], 2)):
        assert row["P.OUTPUT"].size == 1 and float(row["P.OUTPUT"].flat[0]) == x(n)
        assert row["Q.OUTPUT"].size == 1 and float(row["Q.OUTPUT"].flat[0]) == 4


def test_zero_delay_memory_sharing():
    net = load("sharing.ikg")
    for n in range(3):
        net.step()
        same(net.output("Shared.INPUT"), net.output("S.OUTPUT"))
        same(net.output("Shared.OUTPUT"), [x(n)])
        same(net.output("Delayed.OUTPUT"), [x(n - 1)])
        same(net.output("Picked.OUTPUT"), [v(n)[1]])
        same(net.output("Two.OUTPUT"), [x(n), x(n)])
    lines = net.info().splitlines()

    def input_line(module):
        start = lines.index(next(l for l in lines if l.strip().startswith(module + " (")))
        return next(l for l in lines[start + 1:] if "input INPUT" in l)

    assert "shares its source's memory" in input_line("Shared")
    for other in ("Delayed", "Picked", "Two"):
        assert "shares its source's memory" not in input_line(other)


def test_shared_input_is_the_source_array():
    net = load("sharing.ikg")
    assert np.shares_memory(net.buffer_array("Shared.INPUT"), net.buffer_array("S.OUTPUT"))
    assert not np.shares_memory(net.buffer_array("Picked.INPUT"), net.buffer_array("V.OUTPUT"))


def test_overlaid_connections_later_or_zero_delay_over_earlier_sized_by_the_largest():
    net = load("overlay.ikg")
    trace_ = trace(net, ["X.OUTPUT", "Y.OUTPUT", "Z.OUTPUT", "F.OUTPUT", "D.OUTPUT"], 3)
    same(trace_[0]["X.OUTPUT"], [5, 8, 9])
    # a vector over a matrix: in its first row (the reference does not say)
    same(trace_[0]["Y.OUTPUT"], [[7, 8, 9], [3, 4, 0]])
    same(trace_[0]["Z.OUTPUT"], [7, 1, 2])           # a target selector over a whole one
    same(trace_[0]["F.OUTPUT"], [1, 2, 7, 8, 9])      # flatten: end to end, as declared
    # K1 over delay 2 is declared later, but a zero-delay connection is copied last in
    # Ikaros 3 (just before its target ticks): K2 wins where they overlap
    for row in trace_:
        same(row["D.OUTPUT"], [7, 8, 9])
