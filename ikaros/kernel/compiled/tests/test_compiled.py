"""The compiled tick computes what the modules' Python ticks compute, takes parameter
changes at the next tick, reports what the Python ticks report, and is chosen as set."""
import os
import subprocess
import sys

import threading

import numpy as np
import pytest

import ikaros
from ikaros.errors import ModelError, RunError
from ikaros.kernel import compiled
from ikaros.kernel.compiled import ops
from ikaros.kernel.compiled.plan import CompiledRun

pytest.importorskip("numba", reason="the compiled tick needs numba (pip install ikaros[fast])")

SPECIAL = [1.5, -2.0, 0.0, -0.0, np.nan, np.inf, -np.inf, 3e38, 1e-40, 0.7]
OTHER = [0.5, 0.0, -3.0, 2.0, 1.0, -np.inf, np.nan, 2.0, -1e-40, 0.7]

ALL_OPERATIONS = '''<group name="Ops">
    <module class="Constant" name="A" data="1 0 0 0 0 0 0 0 0 0"/>
    <module class="Constant" name="B" data="1 0 0 0 0 0 0 0 0 0"/>
    <module class="Constant" name="K" data="2 5"/>
    <module class="Add" name="Add"/>
    <module class="Subtract" name="Sub"/>
    <module class="Subtract" name="Copy"/>
    <module class="Multiply" name="Mul"/>
    <module class="Divide" name="Div"/>
    <module class="Max" name="Max"/>
    <module class="Min" name="Min"/>
    <module class="Scale" name="Scale" factor="0.3"/>
    <module class="Scale" name="ScaleBy" factor="-1.7"/>
    <module class="Abs" name="Abs"/>
    <module class="Tanh" name="Tanh"/>
    <module class="Threshold" name="Binary" threshold="0.5"/>
    <module class="Threshold" name="Linear" threshold="0.5" type="linear"/>
    <module class="Threshold" name="Bypass" bypass="yes"/>
    <module class="Sum" name="Sum"/>
    <module class="Sum" name="SumFinite"/>
    <module class="Integrator" name="Leak" alpha="0.75" beta="0.3"/>
    <module class="Integrator" name="Clip" alpha="1" beta="1" min="-2" max="4.5"/>
    <module class="Integrator" name="Low" alpha="1" beta="0.5" min="1"/>
    <connection source="A.OUTPUT" target="Add.INPUT1" delay="0"/>
    <connection source="B.OUTPUT" target="Add.INPUT2" delay="0"/>
    <connection source="A.OUTPUT" target="Sub.INPUT1" delay="0"/>
    <connection source="B.OUTPUT" target="Sub.INPUT2" delay="0"/>
    <connection source="A.OUTPUT" target="Copy.INPUT1" delay="0"/>
    <connection source="A.OUTPUT" target="Mul.INPUT1" delay="0"/>
    <connection source="B.OUTPUT" target="Mul.INPUT2" delay="0"/>
    <connection source="A.OUTPUT" target="Div.INPUT1" delay="0"/>
    <connection source="B.OUTPUT" target="Div.INPUT2" delay="0"/>
    <connection source="A.OUTPUT" target="Max.INPUT1" delay="0"/>
    <connection source="B.OUTPUT" target="Max.INPUT2" delay="0"/>
    <connection source="A.OUTPUT" target="Min.INPUT1" delay="0"/>
    <connection source="B.OUTPUT" target="Min.INPUT2" delay="0"/>
    <connection source="A.OUTPUT" target="Scale.INPUT" delay="0"/>
    <connection source="B.OUTPUT" target="ScaleBy.INPUT" delay="0"/>
    <connection source="K.OUTPUT" target="ScaleBy.SCALE" delay="0" sourceoffset="1" size="1"/>
    <connection source="A.OUTPUT" target="Abs.INPUT" delay="0"/>
    <connection source="A.OUTPUT" target="Tanh.INPUT" delay="0"/>
    <connection source="A.OUTPUT" target="Binary.INPUT" delay="0"/>
    <connection source="A.OUTPUT" target="Linear.INPUT" delay="0"/>
    <connection source="A.OUTPUT" target="Bypass.INPUT" delay="0"/>
    <connection source="A.OUTPUT" target="Sum.INPUT" delay="0"/>
    <connection source="Scale.OUTPUT" target="SumFinite.INPUT" delay="0" sourceoffset="0" size="4"/>
    <connection source="Scale.OUTPUT" target="SumFinite.INPUT" delay="0" sourceoffset="8" size="2"/>
    <connection source="B.OUTPUT" target="Leak.INPUT" delay="0"/>
    <connection source="K.OUTPUT" target="Clip.INPUT" delay="0"/>
    <connection source="B.OUTPUT" target="Low.INPUT"/>
</group>'''


def _load(tmp_path, text, name="m.ikg", **overrides):
    path = tmp_path / name
    path.write_text(text)
    return ikaros.load(str(path), **overrides)


def _outputs(net):
    return {p: net.output(p + ".OUTPUT") for p in net.modules}


def _pair(tmp_path, text):
    return _load(tmp_path, text, "a.ikg", compiled="no"), _load(tmp_path, text, "b.ikg",
                                                                  compiled="yes")


def _same(plain, fast, tanh_ulp=3):
    for path, expected in _outputs(plain).items():
        got = fast.output(path + ".OUTPUT")
        if path == "Tanh":
            ulp = np.abs(got.view(np.int32).astype(np.int64) -
                         expected.view(np.int32).astype(np.int64))
            assert ulp.max() <= tanh_ulp, (path, got, expected)
        else:
            assert np.array_equal(got, expected, equal_nan=True), (path, got, expected)
            assert np.array_equal(np.signbit(got), np.signbit(expected)), (path, got, expected)


def test_every_operation_computes_what_its_python_tick_computes(tmp_path):
    plain, fast = _pair(tmp_path, ALL_OPERATIONS)
    assert fast.compiled_modules == len(fast.schedule) == 22
    assert sum(isinstance(step, CompiledRun) for step in fast.plan.sequence) == 1
    with np.errstate(all="ignore"):
        for tick in range(6):
            for net in (plain, fast):
                net.set_parameter("A.data", np.roll(SPECIAL, tick))
                net.set_parameter("B.data", np.roll(OTHER, 2 * tick))
                net.step()
            _same(plain, fast)
    # independent checks of a few
    a, b = np.roll(SPECIAL, 5).astype(np.float32), np.roll(OTHER, 10).astype(np.float32)
    np.testing.assert_array_equal(fast.output("Div.OUTPUT"),
                                  np.where(b == 0, 0, a / np.where(b == 0, 1, b)))
    np.testing.assert_array_equal(fast.output("Linear.OUTPUT"),
                                  np.maximum(a - np.float32(0.5), 0))
    assert fast.output("Clip.OUTPUT").tolist() == [4.5, 4.5]     # 2, 4, 6 and 5, 10: clipped


def test_a_parameter_changed_while_running_takes_effect_at_the_next_tick(tmp_path):
    plain, fast = _pair(tmp_path, ALL_OPERATIONS)
    changes = [("Scale.factor", -4), ("ScaleBy.factor", 0.125), ("Binary.threshold", -1),
               ("Linear.type", "binary"), ("Bypass.bypass", False), ("Leak.alpha", 0.5),
               ("Clip.max", ""), ("Low.min", "-1"), ("K.data", "[7, 9]"), ("Tanh.debug", False)]
    for tick in range(len(changes) + 2):
        if tick < len(changes):
            for net in (plain, fast):
                net.set_parameter(*changes[tick])
        for net in (plain, fast):
            net.step()
        _same(plain, fast)
    assert fast.output("Scale.OUTPUT")[0] == np.float32(1) * np.float32(-4)
    assert fast.output("K.OUTPUT").tolist() == [7, 9]
    assert fast.output("ScaleBy.OUTPUT")[0] == np.float32(np.float32(1) * np.float32(0.125)) * 9


def test_a_module_whose_parameters_cannot_be_compiled_runs_its_python_tick(tmp_path, capsys):
    plain, fast = _pair(tmp_path, ALL_OPERATIONS)
    for net in (plain, fast):
        net.set_parameter("Tanh.debug", True)
        net.step()
    assert capsys.readouterr().out.count("Tanh: [0.7616") == 2    # printed by both
    run = fast.plan.fused[fast.modules["Tanh"]]
    assert [p for p in run.pieces if not isinstance(p, tuple)] == [fast.modules["Tanh"]]
    _same(plain, fast, tanh_ulp=0)                # its own tick: NumPy's tanh
    fast.set_parameter("Tanh.debug", False)
    assert run.span is not None                   # back to one call
    fast.step()
    assert capsys.readouterr().out == ""


def test_a_bad_integrator_limit_stops_the_run_naming_the_module(tmp_path):
    fast = _load(tmp_path, ALL_OPERATIONS, compiled="yes")
    fast.step()
    fast.set_parameter("Clip.min", "lots")
    with pytest.raises(RunError, match="min must be a number or empty"):
        fast.step()
    assert fast.log[-1][2] == "Clip"


def test_division_by_zero_warns_once_as_the_python_tick_does(tmp_path):
    fast = _load(tmp_path, ALL_OPERATIONS, compiled="yes")
    fast.set_parameter("B.data", OTHER)            # has a zero
    fast.run(ticks=3)
    warnings = [entry for entry in fast.log if "division by zero" in entry[3]]
    assert [(w[0], w[2]) for w in warnings] == [(0, "Div")]
    assert fast.output("Div.OUTPUT")[1] == 0


MIXED = '''<group name="M">
    <module class="Constant" name="C" data="1 2 3 4"/>
    <module class="Scale" name="S1" factor="2"/>
    <module class="Sweep" name="P" min="0" max="100" step="1"/>
    <module class="Add" name="A"/>
    <module class="Scale" name="S2" factor="3"/>
    <module class="Scale" name="Slow" factor="5" period="2"/>
    <module class="Concat" name="Cat"/>
    <module class="Scale" name="S3" factor="0.5"/>
    <module class="Abs" name="Strided"/>
    <connection source="C.OUTPUT" target="S1.INPUT" delay="0"/>
    <connection source="S1.OUTPUT[0:4:-2]" target="Strided.INPUT" delay="0"/>
    <connection source="S1.OUTPUT" target="A.INPUT1" delay="0"/>
    <connection source="C.OUTPUT" target="A.INPUT2" delay="0" sourceoffset="0" size="2"/>
    <connection source="S1.OUTPUT" target="A.INPUT2" delay="0" sourceoffset="3" size="1"/>
    <connection source="P.OUTPUT" target="A.INPUT2" delay="0"/>
    <connection source="C.OUTPUT" target="S2.INPUT" delay="0"/>
    <connection source="S2.OUTPUT" target="Slow.INPUT" delay="0"/>
    <connection source="A.OUTPUT" target="Cat.INPUT" delay="0"/>
    <connection source="S2.OUTPUT" target="Cat.INPUT" delay="0"/>
    <connection source="Cat.OUTPUT" target="S3.INPUT" delay="0"/>
</group>'''


def test_python_modules_run_between_compiled_stretches_in_a_valid_order(tmp_path):
    plain, fast = _pair(tmp_path, MIXED)
    kinds = []
    for step in fast.plan.sequence:        # a Python module's calls: its copies, its tick
        kind = "compiled" if isinstance(step, CompiledRun) else fast.plan.owner[step].path
        if kind == "compiled" or kind not in kinds:
            kinds.append(kind)
    # P (Python) feeds A; S2 does not wait for it and joins C and S1's stretch; Slow
    # (period 2) and Cat stay in Python
    assert kinds == ["P", "compiled", "Slow", "Cat", "compiled"]
    run = fast.plan.sequence[1]
    assert [m.path for m in run.members] == ["C", "S1", "A", "S2", "Strided"]
    for _ in range(5):
        plain.step()
        fast.step()
        _same(plain, fast)
    # INPUT2 is P, S1[3], C[0:2] (the last declared first); P: 5 at tick 4
    assert fast.output("A.OUTPUT").tolist() == [2 + 5, 4 + 8, 6 + 1, 8 + 2]
    assert fast.output("Strided.OUTPUT").tolist() == [6, 2]
    codes = fast.plan.sequence[1].table.code[:, 0].tolist()
    assert codes.count(ops.GATHER) == 1


SMALL = '''<group name="S">
    <module class="Constant" name="C" data="1 2"/>
    <module class="Scale" name="S" factor="2"/>
    <connection source="C.OUTPUT" target="S.INPUT" delay="0"/>
</group>'''


def test_the_setting_chooses_the_compiled_tick(tmp_path, monkeypatch):
    monkeypatch.delenv("IKAROS_COMPILED", raising=False)
    assert _load(tmp_path, SMALL).compiled_modules == 0            # auto: too few
    assert _load(tmp_path, SMALL, compiled="yes").info().endswith(
        "Compiled tick: 2 of 2 modules")
    assert _load(tmp_path, SMALL, compiled="yes").compiled_modules == 2
    assert _load(tmp_path, SMALL, compiled="auto").compiled_modules == 0
    monkeypatch.setenv("IKAROS_COMPILED", "1")
    assert _load(tmp_path, SMALL).compiled_modules == 2
    assert _load(tmp_path, SMALL, compiled="no").compiled_modules == 0
    monkeypatch.setenv("IKAROS_COMPILED", "0")
    assert _load(tmp_path, SMALL, compiled="yes").compiled_modules == 0
    with pytest.raises(ModelError, match='compiled="fast" must be auto, yes or no'):
        _load(tmp_path, SMALL, compiled="fast")


def test_auto_compiles_a_model_with_enough_compilable_modules(tmp_path, monkeypatch):
    monkeypatch.delenv("IKAROS_COMPILED", raising=False)
    n = compiled.AUTO_MINIMUM
    chain = "".join(f'<module class="Scale" name="S{i}" factor="1.01"/>'
                    f'<connection source="{"C" if i == 0 else f"S{i - 1}"}.OUTPUT" '
                    f'target="S{i}.INPUT" delay="0"/>' for i in range(n))
    net = _load(tmp_path, f'<group><module class="Constant" name="C" data="1"/>{chain}</group>')
    assert net.wait_compiled(timeout=60) == n + 1       # made in the background
    net.step()
    assert net.output(f"S{n - 1}.OUTPUT")[0] == pytest.approx(1.01 ** n, rel=1e-5)


def _mixed_model(n: int) -> str:
    """n stages of Add, Multiply, Scale and Integrator over 3 elements, with delay-1
    inputs (Add: feedback from three stages on) (no Tanh, so the two plans agree bit for bit)."""
    parts = ['<group><module class="Constant" name="C" data="0.5 -1.25 2"/>']
    for i in range(n):
        prev = "C" if i == 0 else f"M{i - 1}"
        kind = ("Add", "Multiply", "Scale", "Integrator")[i % 4]
        if kind in ("Add", "Multiply"):
            other = f"M{max(i - 3, 0)}" if kind == "Add" else "C"
            parts.append(f'<module class="{kind}" name="M{i}"/>'
                         f'<connection source="{prev}.OUTPUT" target="M{i}.INPUT1" delay="0"/>'
                         f'<connection source="{other}.OUTPUT" target="M{i}.INPUT2"/>')
        elif kind == "Scale":
            parts.append(f'<module class="Scale" name="M{i}" factor="0.9"/>'
                         f'<connection source="{prev}.OUTPUT" target="M{i}.INPUT" delay="0"/>')
        else:
            parts.append(f'<module class="Integrator" name="M{i}" alpha="0.5" beta="0.25"/>'
                         f'<connection source="{prev}.OUTPUT" target="M{i}.INPUT" delay="0"/>')
    return "".join(parts) + "</group>"


def test_auto_switches_to_the_compiled_plan_at_a_tick_boundary(tmp_path, monkeypatch):
    """auto: the network ticks on the NumPy plan while the compiled plan is made in the
    background (held back here until tick 5), takes it at the start of the next tick, and
    every output agrees bit for bit with the NumPy kernel tick by tick, before and after."""
    monkeypatch.delenv("IKAROS_COMPILED", raising=False)
    release = threading.Event()
    real = compiled.executor

    def slow_executor():
        release.wait(60)
        return real()
    monkeypatch.setattr(compiled, "executor", slow_executor)
    text = _mixed_model(80)
    net = _load(tmp_path, text, compiled="auto")
    reference = _load(tmp_path, text, name="r.ikg", compiled="no")
    assert net.compiled_modules == 0 and net.compiled_since is None
    net.set_parameter("M2.factor", 0.75)           # while the plan is being made
    reference.set_parameter("M2.factor", 0.75)
    for tick in range(12):
        if tick == 5:
            release.set()
            net._background.wait(60)                # ready now: taken before the next tick
            assert net.compiled_modules == 0
        net.step()
        reference.step()
        assert net.compiled_modules == (81 if tick >= 5 else 0)
        for path in net.modules:
            assert net.output(path + ".OUTPUT").tobytes() == \
                reference.output(path + ".OUTPUT").tobytes(), (tick, path)
    assert net.compiled_since == 5
    assert net.parameter("M2.factor") == 0.75
    net.set_parameter("M2.factor", 0.5)            # the compiled plan takes it as well
    reference.set_parameter("M2.factor", 0.5)
    net.step()
    reference.step()
    assert net.output("M79.OUTPUT").tobytes() == reference.output("M79.OUTPUT").tobytes()


def test_auto_does_not_start_numba_during_a_real_time_run(tmp_path, monkeypatch):
    monkeypatch.delenv("IKAROS_COMPILED", raising=False)
    net = _load(tmp_path, _mixed_model(70), tick_duration="0.001")
    net.run(ticks=20, real_time=True)
    assert not net._background.started and net.compiled_modules == 0
    net.step()                                      # not in real time: it starts
    assert net.wait_compiled(timeout=60) == 71
    assert net.compiled_since == 21                 # between ticks: from tick 21 on


def test_auto_without_numba_stays_on_the_numpy_plan(tmp_path, monkeypatch):
    monkeypatch.delenv("IKAROS_COMPILED", raising=False)
    monkeypatch.setattr(compiled, "executor", lambda: None)
    net = _load(tmp_path, _mixed_model(70))
    assert net.wait_compiled(timeout=60) == 0
    net.step()
    assert net.compiled_since is None and net._background is None


def test_without_numba_the_kernel_runs_as_before(tmp_path, monkeypatch):
    monkeypatch.setattr(compiled, "executor", lambda: None)
    net = _load(tmp_path, SMALL, compiled="yes")
    assert net.compiled_modules == 0
    net.step()
    assert net.output("S.OUTPUT").tolist() == [2, 4]


def test_a_subclass_that_overrides_tick_runs_its_own_tick(tmp_path):
    (tmp_path / "Doubler.py").write_text('''
from ikaros.modules.utility.Scale import Scale


class Doubler(Scale):
    """Scales, then doubles."""

    def tick(self):
        super().tick()
        self.OUTPUT *= 2
''')
    net = _load(tmp_path, '''<group>
        <module class="Constant" name="C" data="1 2"/>
        <module class="Doubler" name="D" factor="3"/>
        <connection source="C.OUTPUT" target="D.INPUT" delay="0"/>
    </group>''', compiled="yes")
    assert net.compiled_modules == 1
    net.step()
    assert net.output("D.OUTPUT").tolist() == [6, 12]


CACHE_CHECK = """
import sys
import ikaros
from ikaros.kernel.compiled import kernel
for path in sys.argv[1:]:
    ikaros.load(path, compiled="yes").step()
stats = kernel.execute.stats
print(len(kernel.execute.signatures), sum(stats.cache_hits.values()),
      sum(stats.cache_misses.values()))
"""


def test_the_compiled_function_is_compiled_once_and_then_loaded_from_its_cache(tmp_path):
    """Every model uses the one compiled function (its instructions are data); a new
    process loads it from numba's cache instead of compiling it."""
    (tmp_path / "small.ikg").write_text(SMALL)
    (tmp_path / "ops.ikg").write_text(ALL_OPERATIONS)
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__))))))
    env = dict(os.environ, PYTHONPATH=root + os.pathsep + os.environ.get("PYTHONPATH", ""))
    counts = []
    for _ in range(2):          # the first may compile (when no test did before)
        out = subprocess.run([sys.executable, "-c", CACHE_CHECK, str(tmp_path / "small.ikg"),
                              str(tmp_path / "ops.ikg")], capture_output=True, text=True,
                             env=env, timeout=300, check=True).stdout
        counts.append(tuple(int(x) for x in out.split()[-3:]))
    signatures, hits, misses = counts[1]
    assert (signatures, hits, misses) == (1, 1, 0)
