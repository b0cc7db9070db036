"""A warning a module gives before the first tick (in configure or init) is a model warning:
it names the file, the line of the module's element and the module, is kept in
``net.warnings``, and ``strict`` refuses it. A warning during a tick stays a run message."""
import pytest

import ikaros
from ikaros.errors import ModelError
from ikaros.module import WARNING

CLASS = '''
from ikaros.module import Module, Output


class Warns(Module):
    """Test class: warns in configure, init or tick, as its parameter "when" says."""
    OUTPUT = Output("nothing", size=1)

    def configure(self):
        if self.element.attrs.get("when") == "configure":
            self.warning("said in configure")

    def init(self):
        if self.element.attrs.get("when") == "init":
            self.warning("said in init")

    def tick(self):
        if self.element.attrs.get("when") == "tick":
            self.warning("said in a tick")
'''


def _model(tmp_path, when: str) -> str:
    (tmp_path / "Warns.py").write_text(CLASS)
    path = tmp_path / "m.ikg"
    path.write_text(f'<group>\n  <group name="G">\n'
                    f'    <module class="Warns" name="W" when="{when}"/>\n'
                    f'  </group>\n</group>\n')
    return str(path)


@pytest.mark.parametrize("when", ["configure", "init"])
def test_a_warning_before_the_first_tick_is_a_model_warning(tmp_path, capsys, when):
    filename = _model(tmp_path, when)
    with ikaros.load(filename) as net:
        [warning] = net.warnings
        assert (warning.filename, warning.line) == (filename, 3)
        assert warning.element == '<module name="W"> (G.W)'
        assert warning.message == f"said in {when}"
        assert str(warning) == f'{filename}:3: warning: <module name="W"> (G.W): said in {when}'
        # the run's log has it too, once, under the module's path
        assert [e for e in net.log if e[1] == WARNING] == [(0, WARNING, "G.W",
                                                            warning.located())]
    captured = capsys.readouterr()
    assert captured.err.count(f"said in {when}") == 1
    assert "said in" not in captured.out


@pytest.mark.parametrize("when", ["configure", "init"])
def test_strict_refuses_a_warning_before_the_first_tick(tmp_path, when):
    filename = _model(tmp_path, when)
    with pytest.raises(ModelError) as caught:
        ikaros.load(filename, strict=True)
    assert str(caught.value) == (f'{filename}:3: <module name="W"> (G.W): said in {when} '
                                 f'(an error with --strict)')


def test_a_warning_during_a_tick_stays_a_run_message(tmp_path):
    filename = _model(tmp_path, "tick")
    with ikaros.load(filename, strict=True, quiet=True) as net:
        net.step()
        assert net.warnings == []
        assert [e[1:] for e in net.log if e[1] == WARNING] == [(WARNING, "G.W",
                                                                "said in a tick")]
