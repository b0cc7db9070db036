"""DESIGN §3 and §3.1: parameter lookup and types, variables, expressions, matrix literals
and load-time overrides."""
import pytest

from conformance_util import load, same, trace, x


@pytest.fixture(scope="module")
def params():
    return load("parameters.ikg")


@pytest.fixture(scope="module")
def variables():
    return load("variables.ikg")


def test_own_attribute(params):
    assert params.parameter("Own.p") == 5


def test_group_attribute_nearest_wins(params):
    assert params.parameter("Top.p") == 100
    assert params.parameter("G.InG.p") == 6
    assert params.parameter("G.Inner.Nearest.p") == 7
    assert params.parameter("G.Quiet.Skips.p") == 6


def test_renaming_for_all_modules(params):
    assert params.parameter("Rename.C.p") == 9          # <parameter name=maximum target=p>
    assert params.parameter("Rename.D.p") == 9          # beats the plain attribute p=50
    assert params.parameter("Rename.E.p") == 1.5        # the module's own attribute wins


def test_renaming_for_one_module(params):
    assert params.parameter("Rename.C.q") == 11         # target="C.q"
    assert params.parameter("Rename.D.q") == 60         # plain attribute q


def test_qualified_attribute(params):
    assert params.parameter("Qual.E.p") == 13
    assert params.parameter("Qual.E.q") == 14
    assert params.parameter("Qual.F.p") == 1
    assert params.parameter("Qual.F.q") == 2            # class default


def test_order_within_one_group(params):
    # renaming target="R.p" > renaming target="p" > qualified R.p > plain p
    assert params.parameter("QualVsRename.R.p") == 4
    assert params.parameter("QualVsRename.T.p") == 5


def test_renaming_and_explicit_variable(params):
    assert params.parameter("DoubleRandomizer.R1.max") == 5
    assert params.parameter("DoubleRandomizer.R2.max") == 5


def test_renamed_name_is_looked_up_from_the_renaming_group_outward(params):
    assert params.parameter("Far.Near.M.p") == 21       # maximum is defined one group out
    assert params.parameter("Far.Says.Deep.N.p") == 23  # the nearest group that says p
    assert params.parameter("Far.O.p") == 22


def test_class_default(params):
    assert params.parameter("Defaults.Def.q") == 2
    assert params.parameter("Defaults.Def.k") == 4
    assert params.parameter("Defaults.Def.flag") is False
    assert params.parameter("Defaults.Def.s") == "default"


def test_types(params):
    assert params.parameter("Types.T1.k") == 12
    assert params.parameter("Types.T2.k") == -3
    assert params.parameter("Types.T1.s") == "hello world"
    assert params.parameter("Types.T3.s") == "T-INPUT"
    same(params.parameter("Types.T2.m"), [[1, 2], [3, 4]])


def test_bool_spellings(params):
    assert params.parameter("Types.T1.flag") is True     # yes (from the group)
    assert params.parameter("Types.T2.flag") is False    # off
    assert params.parameter("Types.T3.flag") is True     # on
    assert params.parameter("Types.T4.flag") is False    # 0
    assert params.parameter("Types.T5.flag") is True     # true
    assert params.parameter("Types.T6.flag") is False    # no


def test_options_by_label_or_index(params):
    c = params.parameter("Types.T1.mode")
    b = params.parameter("Types.T2.mode")                # mode="1" is the index of "b"
    assert c in ("c", 2)
    assert b in ("b", 1)


def test_variables_resolved_in_the_defining_scope(variables):
    assert variables.parameter("Outer.Inner.R1.p") == 45
    assert variables.parameter("Outer.Inner.R4.p") == 12
    assert variables.parameter("Outer.Inner.R5.p") == 12


def test_variables_in_class_source_target_and_delay():
    # X's class is @cls = Sink; the connection is @src.OUTPUT -> X.@port with delay @del = 2
    net = load("variables.ikg")
    for n, row in enumerate(trace(net, ["X.OUTPUT"], 5)):
        same(row["X.OUTPUT"], [x(n - 2)])


def test_arithmetic(variables):
    assert variables.parameter("Arith.p") == 7           # @n*2+1
    assert variables.parameter("Arith.q") == 40          # {(@n+1)*10}
    assert variables.parameter("Paren.p") == 0.5         # (@n-1)/4
    assert variables.parameter("Paren.q") == -3          # -@n


def test_nothing_else_is_arithmetic(variables):
    assert variables.parameter("Arith.s") == "abc-1"     # a string parameter
    assert variables.parameter("Delayish.s") == "1:3"
    assert variables.parameter("Listish.s") == "a/b"


def test_inherited_expression_is_evaluated_where_it_is_defined(variables):
    assert variables.parameter("Def.Inherit.p") == 3     # c="@x+1" in Def (x=2), not x=100
    assert variables.parameter("Def.Inherit2.q") == 3    # through <parameter name=c target=q>


LITERALS = {
    "Commas": [[1, 2], [3, 4]],
    "Spaces": [[1, 2], [3, 4]],
    "Row": [1, 2, 3],
    "Ragged": [[1, 2, 3], [4, 0, 0]],
    "Ragged2": [[1, 2], [3, 0]],
    "Trailing": [[1, 2], [3, 4]],
    "Rank3": [[[1, 2], [3, 4]], [[5, 6], [7, 8]]],
    "Commented": [[1, 2], [3, 4]],
    "Negative": [[-1.5, 200], [0.5, 0]],
    "Sized": [1, 2, 3, 0, 0],
    "SizedXY": [[1, 2, 3], [4, 5, 0]],
}


@pytest.mark.parametrize("name", sorted(LITERALS))
def test_matrix_literals(name):
    net = load("literals.ikg")
    same(net.output(f"{name}.OUTPUT"), LITERALS[name])


def test_file_values_without_overrides():
    net = load("overrides.ikg")
    net.step()
    same(net.output("G.OUTPUT"), [2, 4])
    assert net.parameter("P.p") == 3
    assert net.parameter("P.s") == "file"


def test_load_keywords_override_top_group_attributes():
    net = load("overrides.ikg", gain=3, p=10, word="kw")
    net.step()
    same(net.output("G.OUTPUT"), [3, 6])
    assert net.parameter("P.p") == 10
    assert net.parameter("P.s") == "kw"


def test_set_parameter_takes_effect_next_tick():
    net = load("overrides.ikg")
    net.step()
    net.set_parameter("G.factor", 5)
    assert net.parameter("G.factor") == 5
    net.step()
    same(net.output("G.OUTPUT"), [5, 10])
