"""Start gating (Ikaros 3 ``module_start`` and ``start_tick``) and start-up steps."""
from types import SimpleNamespace

import pytest

import ikaros
from ikaros.kernel.gating import start_steps

COUNTER = '''
from ikaros.module import Input, Module, Output


class Counter(Module):
    """OUTPUT: the ticks it ran, and the first of them (-1 until it runs)."""
    INPUT = Input("anything", optional=True)
    OUTPUT = Output("[ticks run, first tick]", shape="2")

    def init(self):
        self.OUTPUT[1] = -1

    def tick(self):
        if self.OUTPUT[0] == 0:
            self.OUTPUT[1] = self.clock.tick
        self.OUTPUT[0] += 1
'''


def _model(tmp_path, body: str, **overrides):
    (tmp_path / "Counter.py").write_text(COUNTER)
    (tmp_path / "m.ikg").write_text(f'<group name="G">{body}</group>')
    return ikaros.load(str(tmp_path / "m.ikg"), **overrides)


def _run(net, ticks: int) -> dict:
    net.run(ticks)
    out = {path: net.output(f"{path}.OUTPUT").tolist() for path in net.modules}
    net.close()
    return out


def test_start_steps_add_the_delays_of_the_first_and_of_all_inputs():
    class Module:                       # stands for a ModuleInstance (hashed by identity)
        def __init__(self, name):
            self.name = name

    m = {name: Module(name) for name in "SABCDL"}

    def run(source, target, delay):
        return SimpleNamespace(source=SimpleNamespace(owner=m[source]),
                               target=SimpleNamespace(owner=m[target]), delay=delay)

    runs = [run("S", "A", 0), run("S", "A", 2), run("A", "B", 1), run("S", "B", 0),
            run("B", "C", 3), run("L", "L", 1), run("S", "D", 1), run("D", "D", 1)]
    steps = start_steps(list(m.values()), runs)
    assert {k.name: v for k, v in steps.items()} == {
        "S": (0, 0), "A": (0, 2), "B": (0, 3), "C": (3, 6),
        "L": (None, None),             # a loop that nothing feeds never gets data
        "D": (1, None)}                # data arrives, but "all" waits for the loop


def test_module_start_and_start_tick(tmp_path):
    out = _run(_model(tmp_path, '''
        <module class="Counter" name="Source"/>
        <module class="Counter" name="Late" start_tick="3"/>
        <module class="Counter" name="Zero" module_start="at_tick" start_tick="0"/>
        <module class="Counter" name="First" module_start="first_data"/>
        <module class="Counter" name="All" module_start="all_data"/>
        <module class="Counter" name="AllLater" module_start="2" start_tick="4"/>
        <module class="Counter" name="Never" module_start="first_data"/>
        <module class="Counter" name="Alone" module_start="all_data"/>
        <connection source="Source.OUTPUT" target="First.INPUT" delay="2"/>
        <connection source="Source.OUTPUT" target="First.INPUT" delay="1:3"/>
        <connection source="Source.OUTPUT" target="All.INPUT" delay="2"/>
        <connection source="Source.OUTPUT" target="All.INPUT" delay="1:3"/>
        <connection source="Source.OUTPUT" target="AllLater.INPUT" delay="1"/>
        <connection source="Never.OUTPUT" target="Never.INPUT"/>'''), 6)
    assert out == {"Source": [6, 0], "Late": [3, 3], "Zero": [6, 0], "First": [5, 1],
                   "All": [3, 3], "AllLater": [2, 4], "Never": [0, -1], "Alone": [6, 0]}


def test_start_gating_takes_variables_and_leaves_the_module_to_python(tmp_path):
    net = _model(tmp_path, '<module class="Counter" name="C" start_tick="@begin"/>'
                           '<module class="Counter" name="D"/>', begin="2")
    c, d = net.modules["C"], net.modules["D"]
    assert (c.first_tick, c.every_tick) == (2, False) and d.every_tick
    assert _run(net, 4)["C"] == [2, 2]


def test_start_gating_of_an_asynchronous_module(tmp_path):
    net = _model(tmp_path, '<module class="Counter" name="C" async="yes" start_tick="2"/>')
    for _ in range(4):
        net.step()
        job = net.async_modules[net.modules["C"]]
        if job.future is not None:
            job.future.result()
    net.step()
    assert net.output("C.OUTPUT").tolist()[1] == 2
    net.close()


def test_start_steps_are_known_in_init(tmp_path):
    net = _model(tmp_path, '''<module class="Counter" name="S"/>
        <module class="Counter" name="T"/>
        <connection source="S.OUTPUT" target="T.INPUT" delay="0,2"/>''')
    assert net.modules["T"].module.start_steps() == (0, 2)
    assert net.modules["S"].module.start_steps() == (0, 0)
    net.close()


@pytest.mark.parametrize("attributes, message", [
    ('module_start="later"', 'module_start="later" must be at_tick, first_data or all_data'),
    ('module_start="3"', 'module_start="3" must be'),
    ('start_tick="-1"', "start_tick must be >= 0"),
    ('start_tick="2junk"', "start_tick: "),
])
def test_bad_start_settings(tmp_path, attributes, message):
    with pytest.raises(ikaros.ModelError, match=rf'm.ikg:1: <module name="C">: {message}'):
        _model(tmp_path, f'<module class="Counter" name="C" {attributes}/>')


def test_the_compiled_tick_leaves_gated_modules_to_python(tmp_path):
    pytest.importorskip("numba", reason="the compiled tick needs numba (pip install "
                                        "ikaros[fast])")
    body = '''<module class="Constant" name="K" data="1 2 3"/>
        <module class="Scale" name="Every" factor="2"/>
        <module class="Scale" name="Later" factor="3" start_tick="2"/>
        <connection source="K.OUTPUT" target="Every.INPUT" delay="0"/>
        <connection source="Every.OUTPUT" target="Later.INPUT" delay="0"/>'''
    traces = {}
    for compiled in ("no", "yes"):
        net = _model(tmp_path, body, compiled=compiled)
        if compiled == "yes":
            assert {inst.path for inst in net.plan.fused} == {"K", "Every"}
        trace = []
        for _ in range(4):
            net.step()
            trace.append(net.output("Later.OUTPUT").tolist())
        net.close()
        traces[compiled] = trace
    assert traces["no"] == traces["yes"] == [[0, 0, 0], [0, 0, 0], [6, 12, 18], [6, 12, 18]]


READY = '''
from ikaros.module import Input, Module, Output


class Ready(Module):
    """Keeps input_ready("INPUT") of every tick."""
    INPUT = Input("anything")
    OUTPUT = Output("nothing", shape="1")

    def init(self):
        self.seen = []

    def tick(self):
        self.seen.append(self.input_ready("INPUT").tolist())
'''


def test_input_ready_says_which_elements_hold_data_from_their_source(tmp_path):
    """A chain S -> C (delay 1) -> R (delay 1) and S -> R (delay 0): the last two elements
    of R's input (from C, two elements, laid after S's: the last declared first) hold data
    from tick 2 (C's step 1 + 1), the first two (from S) from tick 0;
    a delay window counts its largest delay (S -> W with delays 0:2: ready from tick 2)."""
    (tmp_path / "Ready.py").write_text(READY)
    net = _model(tmp_path, '''<module class="Counter" name="S"/>
        <module class="Counter" name="C"/>
        <module class="Ready" name="R"/><module class="Ready" name="W"/>
        <connection source="S.OUTPUT" target="C.INPUT"/>
        <connection source="C.OUTPUT" target="R.INPUT"/>
        <connection source="S.OUTPUT" target="R.INPUT" delay="0"/>
        <connection source="S.OUTPUT" target="W.INPUT" delay="0:2"/>''')
    net.run(3)
    f, t = False, True
    assert net.modules["R"].module.seen == [[t, t, f, f], [t, t, f, f], [t, t, t, t]]
    assert net.modules["W"].module.seen == [[f] * 6, [f] * 6, [t] * 6]
    net.close()
