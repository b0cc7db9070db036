"""DESIGN §3: Ikaros 2 size_* rules, Ikaros 3 shape expressions with fixed-point iteration,
.ikc classes, and the checksum."""
import pytest

import ikaros

from conformance_util import load, same, trace

SHAPES = {
    "Z.LIT": (3,),
    "Z.LITXY": (2, 4),            # size_x=4 size_y=2 -> (rows, cols)
    "Z.PARAM": (7,),
    "Z.PARAMXY": (3, 4),          # size_param_x=w(4) size_param_y=h(3)
    "Z.SET": (2, 3),
    "Z.SETXY": (4, 6),            # width = size of INPUT (6), height = size of INPUT2 (4)
    "Z.SHAPE": (2, 3),
    "Z.EXPR": (3, 13),            # "@h, INPUT.size*2+1"
    "Z.TRANS": (3, 2),            # "INPUT.cols, INPUT.rows"
    "R1.OUTPUT": (3, 13),         # a cascade declared backwards
    "R2.OUTPUT": (3, 13),
    "R3.OUTPUT": (3, 13),
    "R3.INPUT": (3, 13),
    "L1.OUTPUT": (3, 2),          # a loop closed through a delayed connection
    "L2.OUTPUT": (3, 2),
    "L3.OUTPUT": (3, 2),
    "L1.INPUT2": (3, 2),
    "I.OUTPUT": (4,),             # .ikc: size_set="INPUT"
    "I.DOUBLE": (8,),             # .ikc: shape="INPUT.size*2"
    "J.A": (4,),                  # .ikc with code in IkcSizes.py: size_param="n"
    "J.B": (6, 6),                # size_set_x / size_set_y
    "J.C": (2, 4),                # "INPUT.rows, @n"
}


@pytest.mark.parametrize("path", sorted(SHAPES))
def test_output_shapes(path):
    net = load("sizes.ikg")
    assert net.output(path).shape == SHAPES[path]


def test_ikc_class_with_python_code_runs():
    net = load("sizes.ikg")
    assert net.parameter("I.gain") == 3
    net.step()
    same(net.output("I.OUTPUT"), [3, 6, 9, 12])
    same(net.output("I.DOUBLE"), [3] * 8)


def test_ikc_sizes_with_python_code_tick():
    net = load("sizes.ikg")
    assert net.parameter("J.n") == 4
    net.run(ticks=2)                                # M is [[1, 2, 3], [4, 5, 6]]
    same(net.output("J.A"), [4, 4, 4, 4])
    same(net.output("J.B"), [[21] * 6] * 6)
    same(net.output("J.C"), [[1] * 4] * 2)


def test_cascade_values():
    net = load("sizes.ikg")
    rows = trace(net, ["R1.OUTPUT", "R3.OUTPUT"], 3)
    same(rows[0]["R1.OUTPUT"], [[0] * 13] * 3)      # Z's outputs are zero
    same(rows[0]["R3.OUTPUT"], [[-5] * 13] * 3)     # R2's init value, delay 1


def test_checksum_match(capsys):
    net = load("checksum.ikg")
    captured = capsys.readouterr()
    text = captured.out + captured.err
    assert "Checksum match (144)" in text
    assert net.checksum_ok is True


def test_checksum_mismatch_is_reported(capsys):
    net = load("checksum.ikg", checksum=145)
    captured = capsys.readouterr()
    text = captured.out + captured.err
    assert "mismatch" in text.lower() and "144" in text and "145" in text
    assert net.checksum_ok is False


def test_an_ikaros_3_check_sum_is_reported_as_not_verified(capsys):
    net = load("checksum.ikg", check_sum=4312)
    text = capsys.readouterr().out
    assert 'check_sum="4312" (Ikaros 3) is not verified' in text
    assert "Checksum match (144)" in text          # the Ikaros 2 checksum is still checked
    assert net.checksum_ok is True


@pytest.mark.parametrize("shape, expected", [("0.29*100", (29,)), ("4.5", (4,)),
                                             ("2.9999999, 3", (3, 3)), ("@n*0.29", (29,))])
def test_a_fractional_dimension_is_cut_down_unless_it_is_whole_but_for_rounding(
        tmp_path, shape, expected):
    # 0.29*100 is 28.999999999999996 in binary floating point: still 29 samples
    (tmp_path / "m.ikg").write_text(f'<group n="100"><module class="Randomizer" name="R" '
                                    f'shape="{shape}"/></group>')
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        assert net.output("R.OUTPUT").shape == expected
