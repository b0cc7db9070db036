"""DESIGN §3: group aliases (Ikaros 2), group ports (Ikaros 3), addressing, group files as
classes, external groups and textual includes."""
from conformance_util import load, same, trace, x


def test_v2_input_alias_declared_twice_fans_out_and_adds_no_delay():
    net = load("group_aliases.ikg")
    for n, row in enumerate(trace(net, ["Pair.A.OUTPUT", "Pair.B.OUTPUT"], 5)):
        same(row["Pair.A.OUTPUT"], [x(n - 2)])
        same(row["Pair.B.OUTPUT"], [x(n - 2)])


def test_v2_output_alias_as_a_source():
    net = load("group_aliases.ikg")
    rows = trace(net, ["Y.OUTPUT"], 5)
    same(rows[0]["Y.OUTPUT"], [-5])                 # A's init value, delay 1
    for n in range(1, 5):
        same(rows[n]["Y.OUTPUT"], [x(n - 3)])       # 2 (into the alias) + 1 (out of it)


def test_v2_output_aliases_chain_through_nested_groups():
    net = load("group_aliases.ikg")
    for n, row in enumerate(trace(net, ["Z.OUTPUT", "Now.OUTPUT"], 4)):
        same(row["Z.OUTPUT"], [501 + n])            # delay 0 through two aliases
        same(row["Now.OUTPUT"], [500 + n])          # delay 1


def test_v3_ports_delays_add_along_the_hops():
    net = load("group_ports.ikg")
    rows = trace(net, ["H.A.OUTPUT", "H.B.OUTPUT", "Y.OUTPUT"], 6)
    for n, row in enumerate(rows):
        same(row["H.A.OUTPUT"], [x(n - 2)])         # 1 + 1
        same(row["H.B.OUTPUT"], [x(n - 1)])         # 1 + 0
    same(rows[0]["Y.OUTPUT"], [-5])
    for n in range(1, 6):
        same(rows[n]["Y.OUTPUT"], [x(n - 3)])       # 1 + 1 + 0 + 1


def test_v3_ports_with_zero_delays_reproduce_v2_timing():
    net = load("group_ports.ikg")
    for n, row in enumerate(trace(net, ["V2.A.OUTPUT", "Z.OUTPUT"], 4)):
        same(row["V2.A.OUTPUT"], [x(n)])
        same(row["Z.OUTPUT"], [x(n)])


def test_window_on_one_hop_is_shifted_by_the_others():
    net = load("group_ports.ikg")
    for n, row in enumerate(trace(net, ["Win.W.OUTPUT"], 7)):
        same(row["Win.W.OUTPUT"], [[x(n - 5)], [x(n - 4)], [x(n - 3)]])   # longest first


def test_addressing_relative_absolute_and_climbing():
    net = load("addressing.ikg")
    net.step()
    same(net.output("G1.G2.G.INPUT"), [3, 3, 7])    # absolute, relative, climbing
    same(net.output("Down.OUTPUT"), [3])            # relative, downward
    same(net.output("Abs.OUTPUT"), [11])            # climbing source, absolute target


def test_group_file_used_as_a_class():
    net = load("group_files.ikg")
    net.step()
    same(net.output("X.OUTPUT"), [8])                # S1 val="8" overrides Sub's val
    same(net.output("Y.OUTPUT"), [5])                # Sub's own val
    same(net.output("S1.C.OUTPUT"), [8])
    same(net.output("S2.R.OUTPUT"), [-7])


def test_external_group():
    net = load("group_files.ikg")
    net.step()
    same(net.output("Z.OUTPUT"), [9])
    same(net.output("E.C.OUTPUT"), [9])
    same(net.output("E.R.OUTPUT"), [-7])


def test_include_splices_elements():
    net = load("group_files.ikg")
    net.step()
    same(net.output("IncSink.OUTPUT"), [4, 5])
    same(net.output("Q.OUTPUT"), [4, 5])


def test_group_file_loads_on_its_own():
    net = load("Sub.ikg")
    net.step()
    same(net.output("C.OUTPUT"), [5])
    same(net.output("R.OUTPUT"), [-7])
