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


def replay_model(tmp_path, recording, signal, loop="no"):
    return load_body(tmp_path, f"""
        <module class="Replay" name="Sensor" filename="{recording}" signal="{signal}"
                loop="{loop}"/>
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
                              f'signal="Grid.OUTPUT" loop="yes"/>')
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
    with pytest.raises(ModelError, match='cannot read the recording "missing.h5"'):
        load_body(tmp_path, '<module class="Replay" name="R" filename="missing.h5" '
                            'signal="A.B"/>')
    (tmp_path / "other.h5").write_bytes(b"not hdf5")
    with pytest.raises(ModelError, match='cannot read the recording "other.h5"'):
        load_body(tmp_path, '<module class="Replay" name="R" filename="other.h5" '
                            'signal="A.B"/>')
