"""Replay: a recording's outputs played back through a model give the recorded values."""
import numpy as np
import pytest

pytest.importorskip("h5py")
pytest.importorskip("xarray")

from ikaros.errors import ModelError  # noqa: E402
from ikaros.experiments import open_recording  # noqa: E402
from ikaros.testing import load_body  # noqa: E402

RECORDED = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Scale" name="Double" factor="2"/>
<module class="Sweep" name="Grid" outputsize_x="3" outputsize_y="2" min="0" max="1e8" step="0.5"/>
<connection source="Counter.OUTPUT" target="Double.INPUT" delay="0"/>
"""
TICKS = 2500          # more than one block of rows read at a time


@pytest.fixture(scope="module")
def recording(tmp_path_factory):
    folder = tmp_path_factory.mktemp("recorded")
    net = load_body(folder, RECORDED)
    with net.record(str(folder / "run.h5")):
        net.run(ticks=TICKS)
    net.close()
    return str(folder / "run.h5")


def replay_model(tmp_path, recording, signal):
    return load_body(tmp_path, f"""
        <module class="Replay" name="Sensor" filename="{recording}" signal="{signal}"
/>
        <module class="Scale" name="Double" factor="2"/>
        <connection source="Sensor.OUTPUT" target="Double.INPUT" delay="0"/>""")


def test_replay_through_a_model_gives_the_recorded_values(tmp_path, recording):
    recorded = open_recording(recording)
    net = replay_model(tmp_path, recording, "Counter.OUTPUT")
    net.log_level = 0
    played = net.run(ticks=TICKS + 100, record="Double.OUTPUT")
    assert net.stopped and net.tick == TICKS       # end of file after the last row
    np.testing.assert_array_equal(played["Double.OUTPUT"].values,
                                  recorded["Double.OUTPUT"].values)
    net.close()


def test_a_matrix_keeps_its_shape_and_loop_starts_again(tmp_path, recording):
    recorded = open_recording(recording)["Grid.OUTPUT"].values
    net = load_body(tmp_path, f'<module class="Replay" name="R" filename="{recording}" '
                              f'signal="Grid.OUTPUT" end="loop"/>')
    played = net.run(ticks=TICKS + 30, record="R.OUTPUT")["R.OUTPUT"].values
    assert played.shape == (TICKS + 30, 2, 3)
    np.testing.assert_array_equal(played[:TICKS], recorded)
    np.testing.assert_array_equal(played[TICKS:], recorded[:30])
    assert not net.stopped
    net.close()


def test_bad_recordings_and_signals_are_clear_errors(tmp_path, recording):
    with pytest.raises(ModelError, match='has no signal "Arm.X"; it has Counter.OUTPUT, '
                                         'Double.OUTPUT, Grid.OUTPUT'):
        replay_model(tmp_path, recording, "Arm.X")
    with pytest.raises(ModelError, match=f'cannot read the recording {tmp_path}/missing.h5: '
                                         f'No such file or directory'):
        load_body(tmp_path, '<module class="Replay" name="R" filename="missing.h5" '
                            'signal="A.B"/>')
    (tmp_path / "other.h5").write_bytes(b"not hdf5")
    with pytest.raises(ModelError, match=f'cannot read the recording {tmp_path}/other.h5: '
                                         f'.*file signature not found'):
        load_body(tmp_path, '<module class="Replay" name="R" filename="other.h5" '
                            'signal="A.B"/>')


def test_a_module_s_outputs_hold_and_seek(tmp_path, recording):
    recorded = open_recording(recording)
    net = load_body(tmp_path, f'<module class="Replay" name="Counter" filename="{recording}" '
                              f'module="Counter" end="hold"/>')
    played = net.run(ticks=TICKS + 5, record="Counter.OUTPUT")["Counter.OUTPUT"].values
    np.testing.assert_array_equal(played[:TICKS], recorded["Counter.OUTPUT"].values)
    np.testing.assert_array_equal(played[TICKS:, 0], [TICKS] * 5)     # the last row held
    net.command("Counter", "seek", x=1234)
    net.step()
    assert net.output("Counter.OUTPUT")[0] == 1235
    assert net.modules["Counter"].module.row == 1234
    net.close()
    with pytest.raises(ModelError, match="give either signal"):
        load_body(tmp_path, f'<module class="Replay" name="R" filename="{recording}"/>')
    with pytest.raises(ModelError, match='no outputs of module "Nothing"'):
        load_body(tmp_path, f'<module class="Replay" name="R" filename="{recording}" '
                            f'module="Nothing"/>')


def test_a_recorded_model_replays_with_its_groups_and_outputs(tmp_path):
    from ikaros.experiments.replay import replay_network
    model = tmp_path / "model.ikg"
    model.write_text('<group name="Top" stop="5"><group name="Inner">'
                     '<module class="Sweep" name="Counter" step="1" max="1e9"/>'
                     '<module class="Scale" name="Double" factor="2"/>'
                     '<module class="Print" name="Show"/>'
                     '<connection source="Counter.OUTPUT" target="Double.INPUT" delay="0"/>'
                     '<output name="OUT" source="Double.OUTPUT"/></group>'
                     '<view name="V"><plot source="Inner.Double.OUTPUT"/></view></group>')
    import ikaros
    net = ikaros.load(str(model))
    with net.record(str(tmp_path / "run.h5")):
        net.run(ticks=50)
    net.close()
    replayed = replay_network(str(tmp_path / "run.h5"))
    assert sorted(replayed.modules) == ["Inner.Counter", "Inner.Double"]   # Print: no output
    assert {m.entry.name for m in replayed.modules.values()} == {"Replay"}
    ds = replayed.run(ticks=60, record="*")          # runs past the model's stop and holds
    assert not replayed.stopped
    np.testing.assert_array_equal(ds["Inner.Double.OUTPUT"].values[:50, 0],
                                  2 * np.arange(1, 51))
    np.testing.assert_array_equal(replayed.output("Inner.Double.OUTPUT"), [100])
    assert 'plot source="Inner.Double.OUTPUT"' in ikaros.open_recording(
        str(tmp_path / "run.h5")).attrs["model"]
    replayed.close()
