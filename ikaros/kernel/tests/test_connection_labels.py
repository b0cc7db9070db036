"""Connection labels (Ikaros 3 ``label``) and what the module API tells a module about the
connections into its inputs: ``input_parts`` and ``input_label`` (``use_label``)."""
import numpy as np
import pytest

import ikaros

PARTS = '''"""Records what the kernel tells it about its inputs."""
from ikaros.module import Input, Module


class Parts(Module):
    """Keeps input_parts and input_label of its inputs, and INPUT's values by part."""
    INPUT = Input("anything", flatten=True)
    LABELLED = Input("one labelled connection", optional=True, use_label=True)

    def init(self):
        self.parts = self.input_parts("INPUT")
        self.labels = {n: self.input_label(n) for n in ("INPUT", "LABELLED")}

    def tick(self):
        self.values = {p.name: p.values(self.INPUT).tolist() for p in self.parts}
'''


def _load(tmp_path, body, **kw):
    (tmp_path / "Parts.py").write_text(PARTS)
    (tmp_path / "m.ikg").write_text(f'<group name="M" tag="w">{body}</group>')
    return ikaros.load(str(tmp_path / "m.ikg"), **kw)


def _module(net):
    return net.modules["X"].module


def test_each_connection_is_a_part_with_its_label_shape_and_place(tmp_path):
    net = _load(tmp_path, '<module class="Constant" name="A" data="1 2; 3 4"/>'
                          '<module class="Constant" name="B" data="5 6 7"/>'
                          '<module class="Parts" name="X"/>'
                          '<connection source="A.OUTPUT" target="X.INPUT" label="weights"/>'
                          '<connection source="B.OUTPUT[1:3]" target="X.INPUT" delay="0"/>'
                          '<connection source="B.OUTPUT[0]" target="X.INPUT" delay="1:2" '
                          'label="@tag"/>')
    try:
        net.run(ticks=2)
        parts = _module(net).parts
        # in declaration order; an Ikaros 2 file lays the last declared first
        assert [(p.label, p.source, p.shape, list(p.index)) for p in parts] == [
            ("weights", "A.OUTPUT", (2, 2), [4, 5, 6, 7]),
            (None, "B.OUTPUT", (2,), [2, 3]),
            ("w", "B.OUTPUT", (2, 1), [0, 1])]
        assert _module(net).values == {"weights": [[1, 2], [3, 4]], "B.OUTPUT": [6, 7],
                                       "w": [[5], [5]]}
        assert _module(net).labels == {"INPUT": None, "LABELLED": None}
    finally:
        net.close()


@pytest.mark.parametrize("connections, label", [
    ('<connection source="A.OUTPUT" target="X.LABELLED" label="signal"/>', "signal"),
    ('<connection source="A.OUTPUT" target="X.LABELLED" label="signal"/>'
     '<connection source="A.OUTPUT" target="X.LABELLED"/>', "signal"),
    ('<connection source="A.OUTPUT" target="X.LABELLED" label="one"/>'
     '<connection source="A.OUTPUT" target="X.LABELLED" label="two"/>', None),
    ('<connection source="A.OUTPUT" target="X.LABELLED"/>', None)])
def test_an_input_that_uses_labels_takes_its_one_label(tmp_path, connections, label):
    net = _load(tmp_path, '<module class="Constant" name="A" data="1"/>'
                          '<module class="Parts" name="X"/>'
                          '<connection source="A.OUTPUT" target="X.INPUT" label="in"/>'
                          + connections)
    try:
        net.step()
        assert _module(net).labels["LABELLED"] == label
    finally:
        net.close()


def test_use_label_may_be_switched_on_or_off_by_the_model(tmp_path):
    net = _load(tmp_path, '<module class="Constant" name="A" data="1"/>'
                          '<module class="Parts" name="X" INPUT.use_label="yes" '
                          'LABELLED.use_label="no"/>'
                          '<connection source="A.OUTPUT" target="X.INPUT" label="in"/>'
                          '<connection source="A.OUTPUT" target="X.LABELLED" label="l"/>')
    try:
        net.step()
        assert _module(net).labels == {"INPUT": "in", "LABELLED": None}
    finally:
        net.close()


def test_a_label_reaches_through_a_group_input(tmp_path):
    net = _load(tmp_path, '<module class="Constant" name="A" data="3 4"/>'
                          '<group name="G"><input name="IN"/>'
                          '<module class="Parts" name="X"/>'
                          '<connection source="IN" target="X.INPUT"/></group>'
                          '<connection source="A.OUTPUT" target="G.IN" label="outer"/>')
    try:
        net.step()
        parts = net.modules["G.X"].module.parts
        assert [(p.label, p.source, p.shape) for p in parts] == [("outer", "G.IN", (2,))]
    finally:
        net.close()


def test_labels_are_kept_when_the_model_is_saved(tmp_path):
    net = _load(tmp_path, '<module class="Constant" name="A" data="1"/>'
                          '<module class="Parts" name="X"/>'
                          '<connection source="A.OUTPUT" target="X.INPUT" label="kept"/>')
    try:
        out = tmp_path / "saved.ikg"
        net.save(str(out))
        assert 'label="kept"' in out.read_text()
    finally:
        net.close()


def test_an_unconnected_input_has_no_parts(tmp_path):
    net = _load(tmp_path, '<module class="Constant" name="A" data="1"/>'
                          '<module class="Parts" name="X"/>'
                          '<connection source="A.OUTPUT" target="X.INPUT"/>')
    try:
        assert net.modules["X"].module.input_parts("LABELLED") == []
        assert np.array_equal(net.modules["X"].module.input_parts("INPUT")[0].index, [0])
    finally:
        net.close()
