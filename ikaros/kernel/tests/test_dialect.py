"""The model file's Ikaros version (the top group's ``dialect``) as modules see it."""
import pytest

import ikaros
from ikaros.errors import ModelError

MODEL = """<group{attr}>
  <module class="Constant" name="C" data="1, 2"/>
  <module class="Scale" name="S" factor="2"/>
  <connection source="C.OUTPUT" target="S.INPUT"/>
</group>"""


def _dialects(tmp_path, attr):
    path = tmp_path / "m.ikg"
    path.write_text(MODEL.format(attr=attr))
    with ikaros.load(str(path)) as net:
        return sorted({inst.module.dialect for inst in net.modules.values()})


def test_a_file_without_a_dialect_is_ikaros_2(tmp_path):
    assert _dialects(tmp_path, "") == ["2"]


def test_the_top_group_names_the_dialect(tmp_path):
    assert _dialects(tmp_path, ' dialect="3"') == ["3"]


def test_an_unknown_dialect_is_refused_naming_the_file(tmp_path):
    with pytest.raises(ModelError, match=r'm\.ikg:1: .*dialect="4" must be "2"'):
        _dialects(tmp_path, ' dialect="4"')


# --- which dialect a file is (issue 26, part 5) -------------------------------------------

@pytest.mark.parametrize("form", [
    ('<group name="G" check_sum="12">', "</group>"),
    ('<group name="G" real_time="false">', "</group>"),
    ('<group name="G">', '<widget class="plot" name="W" source="C.OUTPUT"/></group>'),
    ('<group name="G">', '<connection source="C.OUTPUT" target="S.INPUT" delay="[2:3]"/>'
                         '</group>'),
])
def test_an_ikaros_3_form_makes_the_file_ikaros_3(tmp_path, form):
    head, tail = form
    text = MODEL.format(attr="").replace("<group>", head).replace("</group>", tail)
    path = tmp_path / "m.ikg"
    path.write_text(text)
    with ikaros.load(str(path), quiet=True) as net:
        assert net.dialect == "3"
        assert {inst.module.dialect for inst in net.modules.values()} == {"3"}


def test_an_external_group_makes_the_file_ikaros_3(tmp_path):
    (tmp_path / "part.ikg").write_text('<group name="P"><module class="Constant" name="C"'
                                       ' data="1"/></group>')
    path = tmp_path / "m.ikg"
    path.write_text('<group name="G"><group name="Part" external="part.ikg"/></group>')
    with ikaros.load(str(path), quiet=True) as net:
        assert net.dialect == "3"


def test_the_attribute_and_the_load_keyword_win_over_what_the_file_contains(tmp_path):
    path = tmp_path / "m.ikg"
    path.write_text('<group name="G" check_sum="1" dialect="2"><module class="Constant" '
                    'name="C" data="1"/></group>')
    with ikaros.load(str(path), quiet=True) as net:
        assert net.dialect == "2"
    with ikaros.load(str(path), quiet=True, dialect=3) as net:
        assert net.dialect == "3"


# --- the tick conventions of each dialect ---------------------------------------------------

DELAYS = """<group name="G">
  <module class="Constant" name="C" data="1, 2"/>
  <module class="Scale" name="One" factor="3"/>
  <module class="Scale" name="Three" factor="1"/>
  <module class="Scale" name="Same" factor="1"/>
  <module class="DelaySequenceSource" name="T"/>
  <connection source="C.OUTPUT" target="One.INPUT"/>
  <connection source="C.OUTPUT" target="Three.INPUT" delay="3"/>
  <connection source="C.OUTPUT" target="Same.INPUT" delay="0"/>
</group>"""


def _run(tmp_path, dialect, ticks=5):
    path = tmp_path / "m.ikg"
    path.write_text(DELAYS)
    rows = []
    with ikaros.load(str(path), quiet=True, dialect=dialect, tick_duration=0.5) as net:
        for _ in range(ticks):
            net.step()
            rows.append((net.output("One.OUTPUT").tolist(), net.output("Three.OUTPUT").tolist(),
                         net.output("Same.OUTPUT").tolist(), net.output("T.OUTPUT").tolist(),
                         net.clock.time))
    return rows


def test_an_ikaros_3_file_numbers_the_first_tick_1_and_delivers_no_init_values(tmp_path):
    # golden/README.md: tick k is numbered k with time k * tick_duration; a Constant
    # (C++: written in its tick) reaches a delay-1 receiver from tick 2 on ([0, 0] on
    # tick 1), a delay-n receiver after n ticks; delay 0 the same tick.
    rows = _run(tmp_path, "3")
    assert [r[0] for r in rows] == [[0, 0]] + [[3, 6]] * 4
    assert [r[1] for r in rows] == [[0, 0]] * 3 + [[1, 2]] * 2
    assert [r[2] for r in rows] == [[1, 2]] * 5
    assert [r[3] for r in rows] == [[1], [2], [3], [4], [5]]
    assert [r[4] for r in rows] == [0.5, 1.0, 1.5, 2.0, 2.5]


def test_an_ikaros_2_file_keeps_first_tick_0_and_init_values_on_it(tmp_path):
    # KERNEL.md §4 (v2): a delay-1 input on tick 0 holds what the source wrote in init,
    # a delay-d input on tick n the value of tick n-d (init's for n-d = -1).
    rows = _run(tmp_path, "2")
    assert [r[0] for r in rows] == [[3, 6]] * 5
    assert [r[1] for r in rows] == [[0, 0]] * 2 + [[1, 2]] * 3
    assert [r[2] for r in rows] == [[1, 2]] * 5
    assert [r[3] for r in rows] == [[0], [1], [2], [3], [4]]
    assert [r[4] for r in rows] == [0.0, 0.5, 1.0, 1.5, 2.0]


def test_a_range_without_brackets_is_half_open_in_an_ikaros_3_file(tmp_path):
    # FORMATS §2.4: Ikaros 3 wraps "1:3" as [1:3] (delays 1 and 2); Ikaros 2 reads 1, 2, 3.
    path = tmp_path / "m.ikg"
    path.write_text('<group name="G"><module class="Constant" name="C" data="1, 2"/>'
                    '<module class="Scale" name="S"/>'
                    '<connection source="C.OUTPUT" target="S.INPUT" delay="1:3"/></group>')
    for dialect, shape in (("2", (3, 2)), ("3", (2, 2))):
        with ikaros.load(str(path), quiet=True, dialect=dialect) as net:
            assert net.output("S.INPUT").shape == shape
