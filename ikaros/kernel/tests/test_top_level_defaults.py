"""The top-level settings have defaults (FORMATS: the last step of a variable's lookup), so
``@tick_duration``, ``@stop`` ... resolve when the top group does not set them."""
import numpy as np
import pytest

import ikaros
from ikaros.kernel.scope import substitute


def _constant(tmp_path, data: str, top: str = "", **load) -> float:
    (tmp_path / "m.ikg").write_text(
        f'<group {top}>\n  <group name="G">\n'
        f'    <module class="Constant" name="C" data="{data}"/>\n  </group>\n</group>\n')
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True, **load) as net:
        assert net.warnings == []
        return net.output("G.C.OUTPUT").tolist()


@pytest.mark.parametrize("dialect, seconds", [("2", 0.01), ("3", 1.0)])
def test_tick_duration_is_the_dialects_default_when_unset(tmp_path, dialect, seconds):
    assert _constant(tmp_path, "@tick_duration", dialect=dialect) == \
        [np.float32(seconds)]


def test_tick_duration_set_on_the_top_group_or_the_command_line_wins(tmp_path):
    assert _constant(tmp_path, "@tick_duration", 'tick_duration="0.05"') == \
        [np.float32(0.05)]
    assert _constant(tmp_path, "@tick_duration", 'tick_duration="0.05"',
                     tick_duration="0.25") == [0.25]


def test_the_other_top_level_settings_have_their_defaults(tmp_path):
    # stop: -1 (no limit); arithmetic works on them
    assert _constant(tmp_path, "@stop") == [-1]
    assert _constant(tmp_path, "{@tick_duration*1000}; @stop+1", dialect="2") == \
        [[10], [0]]
    # filename: the model file; batch_mode, info, real_time and start: false
    (tmp_path / "m.ikg").write_text(
        '<group>\n  <module class="Constant" name="C" data="1"\n'
        '     what="@filename @batch_mode @info @real_time @start"/>\n</group>\n')
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        assert net.warnings == []
        inst = net.modules["C"]
        assert substitute(inst.attrs["what"], inst) == \
            f"{tmp_path / 'm.ikg'} false false false false"


def test_an_undefined_variable_is_still_undefined(tmp_path):
    (tmp_path / "m.ikg").write_text('<group><module class="Constant" name="C" '
                                    'data="@tick_durations+1"/></group>')
    with pytest.raises(ikaros.ModelError, match='Variable "@tick_durations" not defined'):
        ikaros.load(str(tmp_path / "m.ikg"), quiet=True)
