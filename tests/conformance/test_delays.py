"""DESIGN §3: delays, delay windows, execution order and time zero."""
from conformance_util import load, same, trace, v, x


def test_tick_counter_starts_at_zero_and_counts_completed_ticks():
    net = load("delays.ikg")
    assert net.tick == 0
    net.step()
    assert net.tick == 1
    net.run(ticks=4)
    assert net.tick == 5


def test_output_before_first_tick_is_init_value():
    net = load("delays.ikg")
    same(net.output("S.OUTPUT"), [100])
    same(net.output("V.OUTPUT"), [100, 200])
    same(net.output("D1.OUTPUT"), [-1])


def test_single_delays():
    net = load("delays.ikg")
    rows = trace(net, ["D0.OUTPUT", "D1.OUTPUT", "D2.OUTPUT", "D3.OUTPUT"], 7)
    for n, row in enumerate(rows):
        same(row["D0.OUTPUT"], [x(n)])          # delay 0, although D0 is declared before S
        same(row["D1.OUTPUT"], [x(n - 1)])      # default delay 1; tick 0 sees the init value
        same(row["D2.OUTPUT"], [x(n - 2)])
        same(row["D3.OUTPUT"], [x(n - 3)])
    same(rows[0]["D1.OUTPUT"], [100])
    same(rows[1]["D2.OUTPUT"], [100])
    same(rows[0]["D2.OUTPUT"], [0])


def test_inclusive_window_is_longest_delay_first_along_new_leading_axis():
    # Ikaros 2 (FORMATS §7.1): one connection per delay, the last made first
    net = load("delays.ikg")
    for n, row in enumerate(trace(net, ["W13.OUTPUT", "W13.INPUT"], 6)):
        same(row["W13.OUTPUT"], [[x(n - 3)], [x(n - 2)], [x(n - 1)]])   # (3, 1)
        same(row["W13.INPUT"], [[x(n - 3)], [x(n - 2)], [x(n - 1)]])


def test_windows_in_listed_order_with_concatenation_declared():
    net = load("delays.ikg", concatenation="declared")
    for n, row in enumerate(trace(net, ["W13.OUTPUT", "WList.OUTPUT", "WVec.OUTPUT"], 8)):
        same(row["W13.OUTPUT"], [[x(n - 1)], [x(n - 2)], [x(n - 3)]])
        same(row["WList.OUTPUT"], [[x(n - d)] for d in (1, 3, 5, 6)])
        same(row["WVec.OUTPUT"], [v(n - 1), v(n - 2), v(n - 3)])


def test_comma_list_window():
    net = load("delays.ikg")
    for n, row in enumerate(trace(net, ["WList.OUTPUT"], 8)):
        same(row["WList.OUTPUT"], [[x(n - d)] for d in (6, 5, 3, 1)])


def test_bracketed_window_is_half_open():
    net = load("delays.ikg")
    for n, row in enumerate(trace(net, ["WHalf.OUTPUT"], 5)):
        same(row["WHalf.OUTPUT"], [[x(n - 2)], [x(n - 1)]])


def test_bracketed_window_from_zero():
    net = load("delays.ikg")
    for n, row in enumerate(trace(net, ["W03.OUTPUT"], 5)):
        same(row["W03.OUTPUT"], [[x(n - 2)], [x(n - 1)], [x(n)]])


def test_stepped_window_with_zero_delay():
    net = load("delays.ikg")
    for n, row in enumerate(trace(net, ["WStep.OUTPUT"], 7)):
        same(row["WStep.OUTPUT"], [[x(n - 4)], [x(n - 2)], [x(n)]])


def test_window_of_a_vector_source_is_delays_by_elements():
    net = load("delays.ikg")
    for n, row in enumerate(trace(net, ["WVec.OUTPUT"], 6)):
        same(row["WVec.OUTPUT"], [v(n - 3), v(n - 2), v(n - 1)])   # (3, 2)


def test_zero_delay_chain_declared_backwards_runs_in_dependency_order():
    net = load("delay_zero_order.ikg")
    same(net.output("B.OUTPUT"), [-5])
    for n, row in enumerate(trace(net, ["A.OUTPUT", "B.OUTPUT", "C.OUTPUT"], 5)):
        same(row["A.OUTPUT"], [x(n)])
        same(row["B.OUTPUT"], [x(n)])
        same(row["C.OUTPUT"], [x(n)])


def test_init_runs_in_schedule_order():
    # Q <- P <- S, all zero-delay, declared Q, P, S: the Pass modules copy their inputs in
    # init, so they see what S wrote in its init (DESIGN 3.1, time zero).
    net = load("time_zero.ikg")
    same(net.output("S.OUTPUT"), [100])
    same(net.output("P.OUTPUT"), [100])
    same(net.output("Q.OUTPUT"), [100])
    for n, row in enumerate(trace(net, ["P.OUTPUT", "Q.OUTPUT", "L.OUTPUT"], 4)):
        same(row["P.OUTPUT"], [x(n)])
        same(row["Q.OUTPUT"], [x(n)])
        same(row["L.OUTPUT"], [x(n - 1)])


def test_cycles_through_a_delay_are_fine():
    net = load("cycle_delayed.ikg")
    same(net.output("A.OUTPUT"), [0])
    same(net.output("B.OUTPUT"), [0])          # B's init sees A's init value (shared memory)
    for n, row in enumerate(trace(net, ["A.OUTPUT", "B.OUTPUT", "M.OUTPUT", "O.OUTPUT"], 5)):
        same(row["A.OUTPUT"], [n + 1])
        same(row["B.OUTPUT"], [n + 1])
        same(row["M.OUTPUT"], [(n + 1) * 1, (n + 1) * 2, (n + 1) * 3])
        same(row["O.OUTPUT"], [(n + 1) * 1, (n + 1) * 2, (n + 1) * 3])


def test_info_lists_schedule_with_sources_first():
    net = load("delay_zero_order.ikg")
    text = net.info()
    schedule = text.split("Schedule:")[1]
    assert schedule.index("S") < schedule.index("A") < schedule.index("B") < schedule.index("C")
