"""Builder cases beyond the conformance suite: size loops, cycle reports, self-reference."""
import pytest

import ikaros

LEAKY = '''<group name="Osc" gain="0.9">
    <group name="Leaky">
        <input  name="IN"  target="Sum.INPUT1" />
        <output name="OUT" source="Sum.OUTPUT" />
        <module class="Add"   name="Sum" />
        <module class="Scale" name="Decay" factor="@gain" />
        <connection source="Sum.OUTPUT"   target="Decay.INPUT" delay="0" />
        <connection source="Decay.OUTPUT" target="Sum.INPUT2" />
    </group>
    <module class="Constant" name="Kick" data="1 1" />
    <connection source="Kick.OUTPUT" target="Leaky.IN" />
</group>
'''


def _load(tmp_path, text, **overrides):
    (tmp_path / "m.ikg").write_text(text)
    return ikaros.load(str(tmp_path / "m.ikg"), **overrides)


def test_a_size_loop_through_a_delay_takes_its_size_from_outside(tmp_path):
    net = _load(tmp_path, LEAKY)
    values = []
    for _ in range(4):
        net.step()
        values.append(net.output("Leaky.Sum.OUTPUT").tolist())
    assert [v[0] for v in values] == pytest.approx([1, 1.9, 2.71, 3.439])
    assert net.output("Leaky.Decay.OUTPUT").shape == (2,)


TWO_LOOPS = '''<group name="Two">
    <module class="Constant" name="Kick1" data="1 1" />
    <module class="Constant" name="Kick2" data="1 2 3" />
    <module class="Add" name="Tail1" />
    <module class="Add" name="Sum1" />
    <module class="Scale" name="Decay1" factor="0.5" />
    <connection source="Kick1.OUTPUT" target="Tail1.INPUT1" />
    <connection source="Decay1.OUTPUT" target="Tail1.INPUT2" />
    <connection source="Kick1.OUTPUT" target="Sum1.INPUT1" />
    <connection source="Sum1.OUTPUT" target="Decay1.INPUT" delay="0" />
    <connection source="Decay1.OUTPUT" target="Sum1.INPUT2" />
    <module class="Add" name="Sum2" />
    <module class="Scale" name="Decay2" factor="0.5" />
    <connection source="Kick2.OUTPUT" target="Sum2.INPUT1" />
    <connection source="Sum2.OUTPUT" target="Decay2.INPUT" delay="0" />
    <connection source="Decay2.OUTPUT" target="Sum2.INPUT2" />
</group>
'''


def test_sizing_through_delays_goes_on_after_an_output_that_feeds_nothing(tmp_path):
    # Tail1 is the first module the fallback sizes, and its output feeds nothing; both
    # loops (Sum1/Decay1 and Sum2/Decay2) must still be sized (issue 26, part 1).
    net = _load(tmp_path, TWO_LOOPS)
    net.run(ticks=3)
    assert net.output("Tail1.OUTPUT").shape == (2,)
    assert net.output("Sum1.OUTPUT").shape == (2,)
    level = 0.0
    for _ in range(3):           # s(k) = kick + 0.5 s(k-1), s(-1) = 0 (Ikaros 2 file)
        level = 1 + 0.5 * level
    assert net.output("Sum2.OUTPUT").tolist() == pytest.approx([level, 2 * level, 3 * level])


def test_a_zero_delay_cycle_is_reported_before_sizes(tmp_path):
    text = '''<group name="C">
  <module class="Scale" name="A"/>
  <module class="Scale" name="B"/>
  <connection source="A.OUTPUT" target="B.INPUT" delay="0"/>
  <connection source="B.OUTPUT" target="A.INPUT" delay="0"/>
</group>'''
    with pytest.raises(ikaros.ModelError, match="zero-delay cycle: B -> A -> B") as e:
        _load(tmp_path, text)
    assert e.value.line == 5


def test_an_attribute_naming_itself_reads_the_enclosing_value(tmp_path):
    text = '''<group name="G" factor="3">
  <module class="Constant" name="K" data="2"/>
  <module class="Scale" name="S" factor="@factor"/>
  <connection source="K.OUTPUT" target="S.INPUT" delay="0"/>
</group>'''
    net = _load(tmp_path, text)
    net.step()
    assert net.output("S.OUTPUT").tolist() == [6]


def test_bad_top_settings_are_model_errors(tmp_path):
    text = '<group name="G" stop="1.5"><module class="Constant" name="K"/></group>'
    with pytest.raises(ikaros.ModelError, match='stop="1.5" must be a whole number'):
        _load(tmp_path, text)
    with pytest.raises(ikaros.ModelError, match="tick_duration"):
        _load(tmp_path, text.replace('stop="1.5"', 'tick_duration="0"'))


def test_width_and_height_rules_combine(tmp_path):
    (tmp_path / "Hist.py").write_text('''
from ikaros.module import Input, Module, Output


class Hist(Module):
    """Test class: rows from a literal, columns from an input."""
    INDEX = Input("the options")
    OUTPUT = Output("the table", size_y="40", size_set_x="INDEX")
''')
    net = _load(tmp_path, '''<group name="G">
  <module class="Constant" name="K" data="1 2 3"/>
  <module class="Hist" name="H"/>
  <connection source="K.OUTPUT" target="H.INDEX"/>
</group>''')
    assert net.output("H.OUTPUT").shape == (40, 3)


def test_a_fatal_error_wins_over_an_end_of_file_on_the_same_tick(tmp_path):
    (tmp_path / "Both.py").write_text('''
from ikaros.module import Module


class Both(Module):
    """Test class: ends the file and fails on tick 1."""

    def tick(self):
        if self.clock.tick == 1:
            self.end_of_file()
            self.fatal_error("broken")
''')
    net = _load(tmp_path, '<group name="G"><module class="Both" name="B"/></group>')
    net.step()
    with pytest.raises(ikaros.RunError, match="broken"):
        net.step()


def test_a_loop_with_nothing_from_outside_is_still_refused_after_another_loop_is_sized(tmp_path):
    # The fallback goes on while rules make progress, and no further: a size nothing can
    # give is refused, as the original refuses it (issue 26, parts 1 and 7).
    text = TWO_LOOPS.replace('</group>', '''
    <module class="Add" name="Closed" />
    <module class="Scale" name="Back" />
    <connection source="Back.OUTPUT" target="Closed.INPUT1" />
    <connection source="Back.OUTPUT" target="Closed.INPUT2" />
    <connection source="Closed.OUTPUT" target="Back.INPUT" delay="0" />
</group>''')
    with pytest.raises(ikaros.ModelError, match=r'm\.ikg:18: <module name="Closed">: the size of '
                                                r'output "OUTPUT" of Closed could not be resolved'):
        _load(tmp_path, text)
