"""A module whose tick assigns to a port (``self.OUTPUT = [1, 2]``) instead of writing into
it fails the run with an error naming the module, the port and the fix."""
import os
import subprocess
import sys

import numpy as np
import pytest

from ikaros.errors import RunError
from ikaros.testing import load_body

REPLACER = '''
import numpy as np
from ikaros.module import Input, Module, Output, Parameter
class Replacer(Module):
    """Assigns to one of its ports on tick ``at``."""
    INPUT = Input(optional=True)
    OUTPUT = Output(size=2)
    port = Parameter("OUTPUT", "the port to assign to")
    at = Parameter(0, "the tick (-2: in init)")
    def init(self):
        if self.at == -2:
            setattr(self, self.port, np.array([1.0, 2.0], np.float32))
    def tick(self):
        if self.clock.tick == self.at:
            setattr(self, self.port, np.array([1.0, 2.0], np.float32))
        else:
            self.OUTPUT[:] = self.clock.tick
'''


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "Replacer.py").write_text(REPLACER)
    return tmp_path


def test_an_output_replaced_in_a_tick_ends_the_run_naming_module_output_and_fix(folder):
    net = load_body(folder, '<module class="Replacer" name="R" at="3"/>')
    net.log_level = -1
    with pytest.raises(RunError) as e:
        net.run(ticks=10)
    assert str(e.value) == (
        "R: ReplacedPort: the tick replaced its output OUTPUT (self.OUTPUT = ...), so "
        "the value never reaches the output: write into the array instead, "
        "self.OUTPUT[:] = ...")
    assert net.tick == 4
    np.testing.assert_array_equal(net.output("R.OUTPUT"), [2, 2])    # tick 2's value


def test_an_input_assigned_to_ends_the_run(folder):
    net = load_body(folder, '<module class="Constant" name="C" data="5 6"/>\n'
                            '<module class="Replacer" name="R" port="INPUT" at="0"/>\n'
                            '<connection source="C.OUTPUT" target="R.INPUT"/>')
    net.log_level = -1
    with pytest.raises(RunError, match=r"R: ReplacedPort: the tick assigned to its "
                                       r"input INPUT \(self.INPUT = ...\): a module never "
                                       r"replaces or writes its inputs"):
        net.step()


def test_the_command_exits_1_with_the_error_and_no_traceback(folder):
    path = folder / "model.ikg"
    path.write_text('<group name="Test"><module class="Replacer" name="R" at="0"/></group>')
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__)))))
    env = dict(os.environ, PYTHONPATH=root + os.pathsep + os.environ.get("PYTHONPATH", ""))
    done = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-s", "5", str(path)],
                          env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert "R: ReplacedPort: the tick replaced its output OUTPUT" in done.stderr
    assert "self.OUTPUT[:] = ..." in done.stderr


def test_a_module_that_writes_into_its_output_runs_on(folder):
    net = load_body(folder, '<module class="Replacer" name="R" at="-1"/>')
    net.run(ticks=5)
    np.testing.assert_array_equal(net.output("R.OUTPUT"), [4, 4])


def test_an_output_replaced_in_init_is_reported_as_init_before_any_tick(folder):
    from ikaros.errors import ModelError
    for port, what in (("OUTPUT", "replaced its output OUTPUT"),
                       ("INPUT", "assigned to its input INPUT")):
        with pytest.raises(ModelError) as e:
            load_body(folder, f'<module class="Constant" name="C" data="5 6"/>\n'
                              f'<module class="Replacer" name="R" port="{port}" at="-2"/>\n'
                              f'<connection source="C.OUTPUT" target="R.INPUT"/>')
        assert e.value.element == '<module name="R">'
        assert e.value.reason.startswith(f"init failed: ReplacedPort: init {what} "
                                         f"(self.{port} = ...)"), e.value.reason
