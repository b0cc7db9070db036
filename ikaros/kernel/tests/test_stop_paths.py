"""Every way a run ends calls the modules' stop(), so drivers reach their safe state."""
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body

RECORDER = r'''
from ikaros.module import Module, Parameter
class Recorder(Module):
    """Notes in a file that its stop() ran; raises there when told to."""
    interrupt = Parameter(False, "raise KeyboardInterrupt in stop")
    log = Parameter("", "the file")
    def stop(self):
        with open(self.log, "a") as f:
            f.write(self.name + "\n")
        if self.interrupt:
            raise KeyboardInterrupt
'''
FAILING_INIT = '''
from ikaros.module import Module
class FailingInit(Module):
    """Fails in init."""
    def init(self):
        raise OSError("no such device")
'''


def stopped(folder):
    path = folder / "stopped.txt"
    return path.read_text().split() if path.exists() else []


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "Recorder.py").write_text(RECORDER)
    (tmp_path / "FailingInit.py").write_text(FAILING_INIT)
    return tmp_path


def test_modules_already_initialised_are_stopped_when_a_later_init_fails(folder):
    with pytest.raises(ModelError, match="init failed: OSError: no such device"):
        load_body(folder, f'<module class="Recorder" name="A" log="{folder}/stopped.txt"/>\n'
                          '<module class="FailingInit" name="F"/>\n'
                          f'<module class="Recorder" name="C" log="{folder}/stopped.txt"/>')
    assert stopped(folder) == ["A"]


def test_a_ctrl_c_in_one_stop_does_not_skip_the_others(folder):
    net = load_body(folder, f'<module class="Recorder" name="First" interrupt="yes" log="{folder}/stopped.txt"/>\n'
                            f'<module class="Recorder" name="Second" log="{folder}/stopped.txt"/>')
    net.step()
    with pytest.raises(KeyboardInterrupt):
        net.close()
    assert sorted(stopped(folder)) == ["First", "Second"]


@pytest.mark.parametrize("in_a_thread", [False, True], ids=["no loop", "loop running"])
def test_the_controllers_end_stops_the_loop_and_every_module_once(folder, in_a_thread):
    net = load_body(folder, f'<module class="Recorder" name="A" log="{folder}/stopped.txt"/>\n'
                            f'<module class="Recorder" name="B" log="{folder}/stopped.txt"/>')
    ctrl = net.controller
    if in_a_thread:
        ctrl.start("play")
    else:
        net.step()
    ctrl.end()
    assert net.stopped and not ctrl.running
    assert stopped(folder) == ["A", "B"]
    net.close()
    assert stopped(folder) == ["A", "B"]
