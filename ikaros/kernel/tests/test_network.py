"""The run-time API of a built network."""
import tracemalloc

import pytest

import ikaros

MODEL = '''<group name="Top" gain="2">
    <module class="Sweep" name="Ramp" min="0" max="100" step="1"/>
    <group name="Arm">
        <module class="Scale" name="Gain" factor="@gain"/>
        <module class="Constant" name="Bias" data="1 2; 3 4"/>
    </group>
    <module class="Add" name="Sum"/>
    <connection source="Ramp.OUTPUT" target="Arm.Gain.INPUT" delay="0"/>
    <connection source="Arm.Gain.OUTPUT" target="Sum.INPUT1"/>
    <connection source="Ramp.OUTPUT" target="Sum.INPUT2" delay="2"/>
</group>
'''


@pytest.fixture
def net(tmp_path):
    (tmp_path / "m.ikg").write_text(MODEL)
    n = ikaros.load(str(tmp_path / "m.ikg"))
    yield n
    n.close()


def test_time_zero_and_stepping(net):
    assert net.tick == 0
    assert net.output("Ramp.OUTPUT").tolist() == [0]        # written in init: tick -1
    net.step()
    assert net.tick == 1
    assert net.output("Ramp.OUTPUT").tolist() == [1]
    assert net.output("Arm.Gain.OUTPUT").tolist() == [2]
    assert net.output("Sum.OUTPUT").tolist() == [0]         # gain(-1)=0 + ramp(-2)=0
    net.run(ticks=3)
    assert net.tick == 4
    # tick 3: gain(2) = 2*3 = 6, ramp(1) = 2
    assert net.output("Sum.OUTPUT").tolist() == [8]
    assert net.output("Top.Arm.Bias.OUTPUT").tolist() == [[1, 2], [3, 4]]   # top name accepted


def test_set_parameter_takes_effect_from_the_next_tick(net):
    net.step()
    net.set_parameter("Arm.Gain.factor", 0.5)
    assert net.output("Arm.Gain.OUTPUT").tolist() == [2]    # not recomputed
    assert net.parameter("Arm.Gain.factor") == 0.5
    net.step()
    assert net.output("Arm.Gain.OUTPUT").tolist() == [1]    # ramp 2 * 0.5
    net.set_parameter("Arm.Gain.factor", "3*2")
    assert net.parameter("Arm.Gain.factor") == 6
    net.set_parameter("Arm.Bias.data", "5 6; 7 8")
    net.step()
    assert net.output("Arm.Bias.OUTPUT").tolist() == [[5, 6], [7, 8]]


def test_bad_parameter_values_change_nothing(net):
    with pytest.raises(ValueError, match='bad value for parameter "Arm.Gain.factor"'):
        net.set_parameter("Arm.Gain.factor", "abc")
    assert net.parameter("Arm.Gain.factor") == 2
    with pytest.raises(KeyError):
        net.set_parameter("Arm.Gain.nope", 1)
    with pytest.raises(KeyError):
        net.output("Arm.Nope.OUTPUT")


def test_outputs_are_copies_and_arrays_keep_their_identity(net):
    module = net.modules["Arm.Gain"].module
    before = module.OUTPUT
    out = net.output("Arm.Gain.OUTPUT")
    out[0] = 99
    net.run(ticks=5)
    assert module.OUTPUT is before
    assert net.output("Arm.Gain.OUTPUT").tolist() == [10]
    assert module.INPUT.base is not None or module.INPUT is net.modules["Ramp"].module.OUTPUT


def test_no_memory_is_allocated_per_tick(net):
    net.run(ticks=200)
    tracemalloc.start()
    net.run(ticks=10)
    before = tracemalloc.take_snapshot()
    net.run(ticks=2000)
    after = tracemalloc.take_snapshot()
    tracemalloc.stop()
    grown = sum(s.size_diff for s in after.compare_to(before, "filename") if s.size_diff > 0)
    assert grown < 4096


def test_save_gives_the_same_network(net, tmp_path):
    net.set_parameter("Arm.Gain.factor", 3)
    net.save(str(tmp_path / "copy.ikg"))
    again = ikaros.load(str(tmp_path / "copy.ikg"))
    assert again.parameter("Arm.Gain.factor") == 3
    net.run(ticks=5)
    again.run(ticks=5)
    # tick 4: gain(3) = 3 * 4 = 12, ramp(2) = 3
    assert net.output("Sum.OUTPUT").tolist() == again.output("Sum.OUTPUT").tolist() == [15]


def test_after_the_run_ends_stepping_is_an_error(net):
    net.close()
    assert net.stopped
    with pytest.raises(ikaros.RunError, match="the run has ended"):
        net.step()
