"""A user module's ``@compiled`` tick runs in place of its Python tick, many instances per
call, with the same results and with parameter changes taken at the next tick."""
import numpy as np
import pytest

import ikaros
from ikaros.errors import RunError
from ikaros.kernel.compiled.plan import CompiledRun

pytest.importorskip("numba", reason="the compiled tick needs numba (pip install ikaros[fast])")

LEAKY = '''
import numpy as np

from ikaros.module import Input, Module, Output, Parameter, compiled


class Leaky(Module):
    """Moves its output towards its input by ``rate`` each tick; ``hold`` stops it."""

    rate = Parameter(0.25, "the step towards the input")
    hold = Parameter(False, "keep the output as it is")
    INPUT = Input("the signal")
    BIAS = Input("added to the input", optional=True)
    OUTPUT = Output("the smoothed signal", size_set="INPUT")

    def command(self, name, x=0, y=0, value=None):
        if name == "freeze":
            self.hold = True

    def tick(self):
        if self.hold:
            return
        x = self.INPUT if self.BIAS is None else self.INPUT + self.BIAS
        self.OUTPUT += np.float32(self.rate) * (x - self.OUTPUT)

    @compiled
    def compiled_tick(INPUT, BIAS, OUTPUT, rate, hold):
        if hold:
            return
        for i in range(OUTPUT.size):
            x = INPUT[i] + BIAS[i] if BIAS.size else INPUT[i]
            OUTPUT[i] += rate * (x - OUTPUT[i])

'''

LABELLED = '''
from ikaros.module import Input, Module, Output, Parameter, compiled


class Labelled(Module):
    """Copies its input; its compiled tick would need a text parameter: runs in Python."""

    label = Parameter("x", "a text parameter")
    INPUT = Input("the signal")
    OUTPUT = Output("a copy", size_set="INPUT")

    def tick(self):
        self.OUTPUT[...] = self.INPUT

    @compiled
    def compiled_tick(INPUT, OUTPUT, label):
        pass
'''

MODEL = '''<group name="U">
    <module class="Constant" name="C" data="1 2 3"/>
    <module class="Leaky" name="L1"/>
    <module class="Leaky" name="L2" rate="0.5"/>
    <module class="Scale" name="S" factor="2"/>
    <module class="Leaky" name="L3"/>
    <module class="Labelled" name="T"/>
    <connection source="C.OUTPUT" target="L1.INPUT" delay="0"/>
    <connection source="C.OUTPUT" target="L2.INPUT" delay="0"/>
    <connection source="L1.OUTPUT" target="L2.BIAS" delay="0"/>
    <connection source="L2.OUTPUT" target="S.INPUT" delay="0"/>
    <connection source="S.OUTPUT" target="L3.INPUT" delay="0"/>
    <connection source="L3.OUTPUT" target="T.INPUT" delay="0"/>
</group>'''


def test_a_user_modules_compiled_tick_runs_as_its_python_tick(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    (tmp_path / "Leaky.py").write_text(LEAKY)
    (tmp_path / "Labelled.py").write_text(LABELLED)
    (tmp_path / "m.ikg").write_text(MODEL)
    plain = ikaros.load(str(tmp_path / "m.ikg"), compiled="no")
    fast = ikaros.load(str(tmp_path / "m.ikg"), compiled="yes")
    assert fast.compiled_modules == 5                     # all but T
    assert len(list((tmp_path / "cache" / "ikaros" / "compiled").glob("Leaky_*.py"))) == 1
    stretches = [[m.path for m in s.members] for s in fast.plan.sequence
                 if isinstance(s, CompiledRun)]
    assert stretches == [["C"], ["L1", "L2"], ["S"], ["L3"]]
    for tick in range(8):
        if tick == 3:
            for net in (plain, fast):
                net.set_parameter("L1.rate", 0.75)
        if tick == 5:
            for net in (plain, fast):
                net.command("L3", "freeze")         # sets hold: read again after a command
        for net in (plain, fast):
            net.step()
        for path in ("L1", "L2", "S", "L3", "T"):
            assert np.array_equal(fast.output(path + ".OUTPUT"),
                                  plain.output(path + ".OUTPUT")), (tick, path)
    held = fast.output("L3.OUTPUT")
    fast.step()
    assert np.array_equal(fast.output("L3.OUTPUT"), held)
    # L1 after 3 ticks at 0.25 and 5 at 0.75, from 0 towards [1, 2, 3]
    expected = np.zeros(3, np.float32)
    for rate in [0.25] * 3 + [0.75] * 6:
        expected += np.float32(rate) * (np.float32([1, 2, 3]) - expected)
    assert np.array_equal(fast.output("L1.OUTPUT"), expected)


BROKEN = '''
import os

from ikaros.module import Input, Module, Output, compiled


class Broken(Module):
    """Copies its input; its compiled tick calls what numba cannot compile."""

    INPUT = Input("the signal")
    OUTPUT = Output("a copy", size_set="INPUT")

    def tick(self):
        self.OUTPUT[...] = self.INPUT

    @compiled
    def compiled_tick(INPUT, OUTPUT):
        OUTPUT[0] = len(os.getcwd())
'''

CAREFUL = '''
from ikaros.module import Input, Module, Output, Parameter, compiled


class Careful(Module):
    """Copies its input; its compiled tick writes past its output above ``limit``."""

    limit = Parameter(10.0, "the largest first input element that is copied")
    INPUT = Input("the signal")
    OUTPUT = Output("a copy", size_set="INPUT")

    def tick(self):
        if self.INPUT[0] > self.limit:
            raise IndexError("index is out of bounds")
        self.OUTPUT[...] = self.INPUT

    @compiled
    def compiled_tick(INPUT, OUTPUT, limit):
        for i in range(OUTPUT.size + (INPUT[0] > limit)):
            OUTPUT[i] = INPUT[i]
'''


def test_a_compiled_tick_numba_cannot_compile_gives_a_warning_and_runs_in_python(
        tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    (tmp_path / "Broken.py").write_text(BROKEN)
    (tmp_path / "m.ikg").write_text('''<group>
        <module class="Constant" name="C" data="3 4"/>
        <module class="Broken" name="B"/>
        <connection source="C.OUTPUT" target="B.INPUT" delay="0"/>
    </group>''')
    net = ikaros.load(str(tmp_path / "m.ikg"), compiled="yes")
    warnings = [entry for entry in net.log if entry[2] == "B"]
    assert len(warnings) == 1
    assert "the compiled_tick of Broken cannot be compiled, so its Python tick runs: " \
           "TypingError" in warnings[0][3]
    assert net.compiled_modules == 1                   # C only
    net.step()
    assert net.output("B.OUTPUT").tolist() == [3, 4]


def test_an_index_out_of_range_in_a_compiled_tick_stops_the_run_naming_the_module(
        tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    (tmp_path / "Careful.py").write_text(CAREFUL)
    (tmp_path / "m.ikg").write_text('''<group>
        <module class="Constant" name="C" data="3 4"/>
        <module class="Careful" name="A"/>
        <module class="Careful" name="B" limit="5"/>
        <module class="Careful" name="D"/>
        <connection source="C.OUTPUT" target="A.INPUT" delay="0"/>
        <connection source="A.OUTPUT" target="B.INPUT" delay="0"/>
        <connection source="B.OUTPUT" target="D.INPUT" delay="0"/>
    </group>''')
    net = ikaros.load(str(tmp_path / "m.ikg"), compiled="yes")
    assert net.compiled_modules == 4
    net.step()
    assert net.output("D.OUTPUT").tolist() == [3, 4]
    net.set_parameter("B.limit", 2)
    with pytest.raises(RunError, match="IndexError: index is out of bounds"):
        net.step()
    assert net.log[-1][2] == "B"
