"""Several connections into one input and the order of a delay window's slots: Ikaros 2's
order (the connection declared last first, the longest delay first), Ikaros 3's overlay, and
the ``concatenation`` setting that chooses (docs/language.md)."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body

# K1 = [1, 2], K2 = [7, 8, 9], K3 = [5], connected to X in that order (issue 35's example)
THREE = ('<module class="Constant" name="K1" data="1, 2"/>'
         '<module class="Constant" name="K2" data="7, 8, 9"/>'
         '<module class="Constant" name="K3" data="5"/>'
         '<module class="Scale" name="X"/>'
         '<connection source="K1.OUTPUT" target="X.INPUT"/>'
         '<connection source="K2.OUTPUT" target="X.INPUT"/>'
         '<connection source="K3.OUTPUT" target="X.INPUT"/>')


def _input(tmp_path, body, ticks=2, **overrides):
    with load_body(tmp_path, body, quiet=True, **overrides) as net:
        net.run(ticks=ticks)
        return net.output("X.INPUT").tolist()


@pytest.mark.parametrize("overrides, expected", [
    ({}, [5, 7, 8, 9, 1, 2]),                                 # an Ikaros 2 file
    ({"dialect": 3}, [5, 8, 9]),                              # Ikaros 3: overlaid
    ({"concatenation": "declared"}, [1, 2, 7, 8, 9, 5]),
    ({"dialect": 3, "concatenation": "declared"}, [1, 2, 7, 8, 9, 5]),
    ({"concatenation": "overlay"}, [5, 8, 9]),
    ({"dialect": 3, "concatenation": "reversed"}, [5, 7, 8, 9, 1, 2]),
])
def test_three_connections_into_one_input(tmp_path, overrides, expected):
    assert _input(tmp_path, THREE, **overrides) == expected


def test_a_flatten_input_of_an_ikaros_3_file_concatenates_in_declaration_order(tmp_path):
    assert _input(tmp_path, THREE.replace('name="X"', 'name="X" INPUT.flatten="yes"'),
                  dialect=3) == [1, 2, 7, 8, 9, 5]


def test_the_nearest_setting_wins(tmp_path):
    body = ('<module class="Constant" name="A" data="1"/>'
            '<module class="Constant" name="B" data="2"/>'
            '<group name="G" concatenation="declared">'
            '  <module class="Scale" name="Group"/>'
            '  <module class="Scale" name="Module" concatenation="reversed"/>'
            '  <module class="Scale" name="Input" concatenation="reversed" '
            '          INPUT.concatenation="declared"/>'
            '  <group name="P" concatenation="reversed">'
            '    <input name="IN" concatenation="declared"/>'
            '    <module class="Scale" name="S"/>'
            '    <connection source="IN" target="S.INPUT" delay="0"/>'
            '  </group>'
            '</group>' +
            "".join(f'<connection source="{s}.OUTPUT" target="G.{m}.INPUT"/>'
                    for m in ("Group", "Module", "Input") for s in "AB") +
            '<connection source="A.OUTPUT" target="G.P.IN"/>'
            '<connection source="B.OUTPUT" target="G.P.IN"/>')
    with load_body(tmp_path, body, quiet=True, dialect=2) as net:
        net.step()
        got = {m: net.output(f"G.{m}.INPUT").tolist() for m in ("Group", "Module", "Input")}
        assert got == {"Group": [1, 2], "Module": [2, 1], "Input": [1, 2]}
        assert net.output("G.P.S.INPUT").tolist() == [1, 2]


def test_a_bad_setting_is_an_error_naming_the_element(tmp_path):
    with pytest.raises(ikaros.ModelError,
                       match=r'model.ikg:\d+: <module name="X">: concatenation="last" must '
                             r'be one of reversed, overlay, declared'):
        load_body(tmp_path, THREE.replace('name="X"', 'name="X" concatenation="last"'))


@pytest.mark.parametrize("delay, overrides, lanes", [
    ("1:3", {}, [3, 2, 1]),                        # Ikaros 2: the longest delay first
    ("1,3", {}, [3, 1]),
    ("3,1", {}, [1, 3]),                           # the reverse of the listed order
    ("1:3", {"concatenation": "declared"}, [1, 2, 3]),
    ("[1:4]", {}, [1, 2, 3]),                      # an Ikaros 3 file: the listed order
])
def test_the_slots_of_a_delay_window(tmp_path, delay, overrides, lanes):
    # S adds 1 on every tick, so the slot of delay d holds S's value now less d
    body = ('<module class="Sweep" name="S" min="0" max="1000" step="1"/>'
            '<module class="Scale" name="X"/>'
            f'<connection source="S.OUTPUT" target="X.INPUT" delay="{delay}"/>')
    with load_body(tmp_path, body, quiet=True, **overrides) as net:
        net.run(ticks=6)
        now = net.output("S.OUTPUT")[0]
        assert net.output("X.INPUT").reshape(-1).tolist() == [now - d for d in lanes]


def test_in_an_ikaros_3_file_a_zero_delay_connection_wins_over_a_later_delayed_one(tmp_path):
    body = ('<module class="Constant" name="A" data="1, 2"/>'
            '<module class="Sweep" name="S" min="10" max="1000" step="1"/>'
            '<module class="Scale" name="X"/>'
            '<connection source="A.OUTPUT" target="X.INPUT" delay="0"/>'
            '<connection source="S.OUTPUT" target="X.INPUT" delay="1"/>')
    # Ikaros 3 copies delayed connections at the end of a tick and a zero-delay one just
    # before X ticks, so A's element 0 stays; S, declared later, still writes nothing
    assert _input(tmp_path, body, ticks=4, dialect=3) == [1, 2]


def test_a_zero_delay_connection_beside_another_warns_in_an_ikaros_2_file(tmp_path):
    body = ('<module class="Constant" name="A" data="1, 2"/>'
            '<module class="Constant" name="B" data="3"/><module class="Scale" name="X"/>'
            '<connection source="A.OUTPUT" target="X.INPUT"/>\n'
            '<connection source="B.OUTPUT" target="X.INPUT" delay="0"/>')
    with load_body(tmp_path, body, quiet=True) as net:
        [warning] = net.warnings
        assert warning.line == 3 and warning.element == "<connection>"
        assert "X.INPUT is fed over delay 0 and by another connection or delay; Ikaros 2 " \
               "refuses this" in warning.message
    with load_body(tmp_path, body, quiet=True, dialect=3) as net:
        assert net.warnings == []
    with pytest.raises(ikaros.ModelError, match="Ikaros 2 refuses this"):
        load_body(tmp_path, body, strict=True)


def test_a_model_built_in_python_keeps_its_meaning_when_saved(tmp_path):
    model = ikaros.Group("M")
    a = model.module("Constant", "A", data=[1, 2])
    b = model.module("Constant", "B", data=[3])
    s = model.module("Sweep", "S", min=0, max=1000, step=1)
    x, w = model.module("Scale", "X"), model.module("Scale", "W")
    model.connect(a.OUTPUT, x.INPUT)
    model.connect(b.OUTPUT, x.INPUT)
    model.connect(s.OUTPUT, w.INPUT, delay=range(1, 4))
    values = []
    with model.build(quiet=True) as net:
        net.run(ticks=5)
        values.append((net.dialect, net.output("X.INPUT").tolist(),
                       net.output("W.INPUT").reshape(-1).tolist()))
    model.save(str(tmp_path / "m.ikg"))
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        net.run(ticks=5)
        values.append((net.dialect, net.output("X.INPUT").tolist(),
                       net.output("W.INPUT").reshape(-1).tolist()))
    assert values[0] == values[1]
    assert values[0][1] == [3, 1, 2] and len(values[0][2]) == 3
    assert np.all(np.diff(values[0][2]) == 1)          # the longest delay first
