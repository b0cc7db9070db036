"""The task watchdog (top-group task_timeout): a too long tick is reported with its module,
finishes, and then the run stops through the modules' stop()."""
import sys
import threading
import pytest

from ikaros.errors import ModelError, RunError
from ikaros.kernel.compiled.plan import CompiledRun
from ikaros.kernel.watchdog import Watchdog, task_timeout
from ikaros.module import FATAL_ERROR, WARNING
from ikaros.testing import load_body

SLEEPER = r'''
from ikaros.module import Module, Parameter
import time
class Sleeper(Module):
    """Notes its ticks and stop in EVENTS; sleeps ``seconds`` in tick ``at``."""
    seconds = Parameter(0.0, "seconds to sleep", type="float")
    at = Parameter(-1, "the tick on which it sleeps", type="int")
    EVENTS = []
    def tick(self):
        t = self.clock.tick
        self.EVENTS.append(f"{self.name} start {t}")
        if t == self.at:
            time.sleep(self.seconds)
        self.EVENTS.append(f"{self.name} end {t}")
    def stop(self):
        self.EVENTS.append(f"{self.name} stop")
'''


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "Sleeper.py").write_text(SLEEPER)
    return tmp_path


def events(net):
    return type(net.modules["A"].module).EVENTS


def watchdogs():
    return [t for t in threading.enumerate() if t.name == "ikaros-watchdog"]


@pytest.mark.parametrize("text, seconds", [(None, None), ("", None), ("0", None),
                                           ("2", 2.0), ("0.25", 0.25)])
def test_the_setting_in_seconds_with_0_or_unset_for_off(text, seconds):
    assert task_timeout(text, ValueError) == seconds


@pytest.mark.parametrize("text", ["-1", "abc", "inf", "nan"])
def test_a_bad_setting_is_an_error_naming_it(folder, text):
    with pytest.raises(ModelError, match=f'task_timeout="{text}" must be a number of seconds'
                                         r' >= 0 \(0: off\)'):
        load_body(folder, '<module class="Sleeper" name="A"/>', task_timeout=text)


@pytest.mark.parametrize("setting", [{}, {"task_timeout": "0"}])
def test_no_watchdog_thread_when_unset_or_0(folder, setting):
    before = len(watchdogs())
    net = load_body(folder, '<module class="Sleeper" name="A"/>', **setting)
    assert net._watchdog is None and len(watchdogs()) == before
    net.close()


def test_quick_ticks_run_on_and_the_watchdog_ends_with_the_run(folder):
    net = load_body(folder, '<module class="Sleeper" name="A"/>', task_timeout="0.5")
    assert net.task_timeout == 0.5
    thread = net._watchdog._thread
    assert thread.is_alive()
    assert net.run(20) == 20 and net.stop_reason is None
    net.close()
    assert not thread.is_alive()


@pytest.mark.parametrize("threads", ["1", "2"])
@pytest.mark.parametrize("slow", ["A", "B"])
def test_a_too_long_tick_finishes_then_the_run_stops_with_an_error(folder, threads, slow):
    net = load_body(folder, '<module class="Sleeper" name="A"/>\n'
                            '<module class="Sleeper" name="B"/>',
                    task_timeout="0.1", threads=threads)
    net.set_parameter(f"{slow}.seconds", 0.4)
    net.set_parameter(f"{slow}.at", 1)
    log = events(net)
    log.clear()
    net.step()
    with pytest.raises(RunError, match=fr"^{slow}: the tick timed out after 0.1 s "
                                       r"\(task_timeout\)$"):
        net.step()
    assert net.stopped and net.tick == 2
    assert net.stop_reason == (FATAL_ERROR, "the tick timed out after 0.1 s (task_timeout)")
    # both modules finish tick 1; stop() comes after it, once each
    assert log.index(f"{slow} end 1") < min(log.index("A stop"), log.index("B stop"))
    assert {"A end 1", "B end 1"} <= set(log) and len(log) == 10
    warnings = [m for _, level, _, m in net.log if level == WARNING]
    assert warnings == [f"tick 1 exceeded task_timeout (0.1 s) in {slow}; waiting for the "
                        f"tick to finish before stopping"]
    assert not net._watchdog._thread.is_alive()


def test_the_run_loop_stops_after_the_long_tick(folder):
    net = load_body(folder, '<module class="Sleeper" name="A" seconds="0.4" at="3"/>',
                    task_timeout="0.1")
    events(net).clear()
    with pytest.raises(RunError, match="A: the tick timed out"):
        net.run(10)
    assert net.stopped and net.tick == 4
    assert events(net)[-3:] == ["A start 3", "A end 3", "A stop"]


def test_a_fatal_error_of_a_module_is_not_replaced(folder):
    net = load_body(folder, '<module class="Sleeper" name="A"/>', task_timeout="5")
    net.notify(FATAL_ERROR, "A", "broken")
    net.time_out("A", "too long", "timed out")
    assert net.stop_reason == (FATAL_ERROR, "broken")
    with pytest.raises(RunError, match="A: broken"):
        net._end()


def test_a_compiled_stretch_is_named_as_a_whole(folder):
    net = load_body(folder, '<module class="Sleeper" name="A"/>\n'
                            '<module class="Sleeper" name="B"/>', task_timeout="5")
    watchdog: Watchdog = net._watchdog
    stretch = CompiledRun.__new__(CompiledRun)
    stretch.members = list(net.schedule)

    def in_the_stretch(self):
        return watchdog._running_module({threading.get_ident(): sys._getframe()},
                                        threading.get_ident())
    assert in_the_stretch(stretch) == "the compiled stretch A ... B (2 modules)"
    assert in_the_stretch(object()) is None
    net.close()

