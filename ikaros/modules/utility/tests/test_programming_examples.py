"""Tests of the programming examples DelayOne and Summation, and of their listing in
docs/writing-modules.md."""
import os

import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))


def test_delayone_is_a_delay_one_connection(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; 3 4"/>'
                         '<module class="Sweep" name="S" min="0" max="9" step="1"/>'
                         '<module class="DelayOne" name="D"/>'
                         '<module class="DelayOne" name="D2"/>'
                         '<module class="Scale" name="Ref" factor="1"/>'
                         '<connection source="S.OUTPUT" target="D.INPUT" delay="0"/>'
                         '<connection source="S.OUTPUT" target="Ref.INPUT" delay="1"/>'
                         '<connection source="C.OUTPUT" target="D2.INPUT" delay="0"/>')
    try:
        assert net.output("D2.OUTPUT").shape == (2, 2)
        seen = []
        for _ in range(5):
            net.step()
            assert net.output("D.OUTPUT").tolist() == net.output("Ref.OUTPUT").tolist()
            seen.append(float(net.output("D.OUTPUT")[0]))
        assert seen == [0, 1, 2, 3, 4]
        assert net.output("D2.OUTPUT").tolist() == [[1, 2], [3, 4]]
    finally:
        net.close()


def test_summation_adds_element_by_element(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2; 3 4"/>'
                         '<module class="Constant" name="B" data="10 20 30 40"/>'
                         '<module class="Summation" name="S"/>'
                         '<connection source="A.OUTPUT" target="S.INPUT1"/>'
                         '<connection source="B.OUTPUT" target="S.INPUT2"/>')
    try:
        net.step()
        assert net.output("S.OUTPUT").tolist() == [[11, 22], [33, 44]]
    finally:
        net.close()


def test_summation_of_unequal_inputs_is_a_load_error(tmp_path):
    with pytest.raises(ModelError, match="INPUT1 has 2 elements and INPUT2 3"):
        load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
                       '<module class="Constant" name="B" data="1 2 3"/>'
                       '<module class="Summation" name="S"/>'
                       '<connection source="A.OUTPUT" target="S.INPUT1"/>'
                       '<connection source="B.OUTPUT" target="S.INPUT2"/>')


@pytest.mark.parametrize("name", ["DelayOne", "Summation"])
def test_the_guide_shows_the_source_as_it_is(name):
    with open(os.path.join(ROOT, "ikaros", "modules", "utility", f"{name}.py")) as f:
        source = f.read()
    with open(os.path.join(ROOT, "docs", "writing-modules.md")) as f:
        guide = f.read()
    assert f"```python\n{source}```" in guide
