"""A port named like a method of the module API (from an .ikc file, or added at build time)
keeps its name in the model; its attribute gets a trailing underscore."""
import ikaros

RELAY = '''from ikaros.module import Module


class Relay(Module):
    """Copies its input "tick" to its output "stop" (ports declared in Relay.ikc)."""

    def tick(self):
        self.stop_[...] = self.tick_ * 2
'''

RELAY_IKC = '''<class name="Relay">
    <input name="tick"/>
    <output name="stop" size_set="tick"/>
</class>
'''


def test_ports_with_reserved_names_work_and_keep_their_names(tmp_path):
    (tmp_path / "Relay.py").write_text(RELAY)
    (tmp_path / "Relay.ikc").write_text(RELAY_IKC)
    (tmp_path / "m.ikg").write_text('<group name="M"><module class="Constant" name="C" '
                                    'data="1 2"/><module class="Relay" name="R"/>'
                                    '<connection source="C.OUTPUT" target="R.tick" '
                                    'delay="0"/></group>')
    net = ikaros.load(str(tmp_path / "m.ikg"))
    try:
        net.step()
        assert net.output("R.stop").tolist() == [2, 4]
    finally:
        net.close()


def test_a_python_class_may_declare_a_reserved_parameter_name_in_name_underscore():
    import pytest
    from ikaros.module import Module, Parameter

    class Napper(Module):
        init_ = Parameter(1.5, "seconds", name="init")

    assert [p.name for p in Napper.description.parameters] == ["init"]
    with pytest.raises(TypeError, match="'init' is a reserved name"):
        class Wrong(Module):
            init_seconds = Parameter(1.5, "seconds", name="init")
