"""SequenceRecorder in an Ikaros 3 file: Ikaros 3's interface (IKAROS3-INTERFACES: its ports,
sizes and defaults) and the behaviour its description gives, against values computed here."""
import json

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body


def recorder(tmp_path, params="", source='<module class="Constant" name="In" data="0.5 0.5 0.5 0.5"/>',
             extra="", dt="0.1"):
    body = (source + f'\n<module class="SequenceRecorder" name="R" {params}/>\n'
            '<connection source="In.OUTPUT" target="R.INPUT" delay="0"/>\n' + extra)
    return load_body(tmp_path, body, dialect="3", tick_duration=dt)


def sequences_file(tmp_path, *sequences):
    (tmp_path / "Sequences").mkdir(exist_ok=True)
    (tmp_path / "Sequences" / "sequence.json").write_text(json.dumps(
        {"sequences": [{"name": name, "channels": channels} for name, channels in sequences]}))


def test_the_ikaros_3_interface_and_its_sizes(tmp_path):
    net = recorder(tmp_path)
    shapes = {name: net.output(f"R.{name}").shape for name in
              ("PLAYING", "COMPLETED", "COLOR", "LIMITING", "ERROR", "SMOOTHING_START", "TARGET", "OUTPUT",
               "ACTIVE", "CAN_PLAY")}
    assert shapes == {"PLAYING": (64,), "COMPLETED": (64,), "COLOR": (64, 3), "LIMITING": (1,), "ERROR": (1,),
                      "SMOOTHING_START": (4,), "TARGET": (4,), "OUTPUT": (4,), "ACTIVE": (4,), "CAN_PLAY": (4,)}
    net.close()
    with pytest.raises(ModelError, match=r"INPUT is not connected \(required in an Ikaros 3 file\)"):
        load_body(tmp_path, '<module class="SequenceRecorder" name="R"/>', dialect="3").step()


def test_a_sequence_plays_with_its_interpolation_range_and_end(tmp_path):
    """Channel 0 linear from 0 at 0 s to 1 at 1 s; channel 1 steps (interpolation 0) from 0.2
    to 0.8 at 0.5 s; channel 2 beyond range_max 0.6 (clipped); channel 3 has no keyframes."""
    sequences_file(tmp_path, ("A", [[[0, 0], [1, 1]], [[0, 0.2], [0.5, 0.8]], [[0, 0.9]], []]))
    net = recorder(tmp_path, 'smoothing_time="0" interpolation="1, 0, 1, 1" range_max="1, 1, 0.6, 1" '
                             'default_output="0, 0, 0, 0.3"')
    try:
        assert net.output("R.CAN_PLAY").tolist() == [0, 0, 0, 0]      # shown from the first tick
        net.command("R", "play")
        rows = []
        for _ in range(12):
            net.step()
            rows.append((net.output("R.OUTPUT").copy(), net.output("R.PLAYING")[0], net.output("R.COMPLETED")[0]))
        heads = np.minimum(0.1 * np.arange(12), 1.0)
        expected0 = np.clip(heads, 0, 1)
        expected1 = np.where(heads < 0.5, 0.2, 0.8)
        assert [r[0][0] for r in rows] == pytest.approx(expected0, abs=1e-5)
        assert [r[0][1] for r in rows] == pytest.approx(expected1, abs=1e-5)
        assert all(r[0][2] == pytest.approx(0.6) for r in rows)
        assert all(r[0][3] == pytest.approx(0.3) for r in rows[:1])     # no keyframes: default_output
        completed = [k for k, r in enumerate(rows) if r[2]]
        assert completed == [10]                               # the end, 1 s, is played on the 11th tick
        assert [r[1] for r in rows] == [1] * 10 + [0] * 2
        assert net.output("R.CAN_PLAY").tolist() == [1, 1, 1, 0]
        assert net.modules["R"].module.time == "00:01:000"
    finally:
        net.close()


def test_smoothing_max_speed_and_limiting(tmp_path):
    sequences_file(tmp_path, ("A", [[[0, 1], [2, 1]], [[0, 1], [2, 1]]]))
    net = recorder(tmp_path, 'channels="2" smoothing_time="0.4" max_speed="0, 1" range_max="2, 2" '
                             'default_output="0, 0"', source='<module class="Constant" name="In" data="0 0"/>')
    try:
        net.command("R", "play")
        outputs, limiting = [], []
        for _ in range(6):
            net.step()
            outputs.append(net.output("R.OUTPUT").copy())
            limiting.append(net.output("R.LIMITING")[0])
        assert net.output("R.SMOOTHING_START").tolist() == [0, 0]
        # channel 0: from 0 to 1 over 0.4 s (4 ticks); channel 1: at most 1 a second, 0.1 a tick
        assert [o[0] for o in outputs] == pytest.approx([0, 0.25, 0.5, 0.75, 1, 1], abs=1e-5)
        assert [o[1] for o in outputs] == pytest.approx([0, 0.1, 0.2, 0.3, 0.4, 0.5], abs=1e-5)
        assert limiting == [0, 1, 1, 1, 1, 1]
    finally:
        net.close()


def test_recording_is_simplified_and_replaces_the_stretch_recorded(tmp_path):
    """A sine recorded on channel 0 (mode 1) for 2 s: simplified, no value moves more than
    simplify_epsilon from what was recorded."""
    source = '<module class="Oscillator" name="In" frequency="0.5 0 0 0"/>'
    net = recorder(tmp_path, 'channel_mode="1, 0, 0, 0" simplify_epsilon="0.05" range_min="-1, 0, 0, 0"',
                   source=source)
    try:
        net.command("R", "record")
        recorded = []
        for _ in range(21):
            net.step()
            recorded.append(net.output("In.OUTPUT")[0])
        net.command("R", "stop")
        keys = net.modules["R"].module._player.sequences[0].channels[0]
        assert 2 < len(keys) < 20
        times = np.array([t for t, _ in keys])
        values = np.array([v for _, v in keys])
        sampled = 0.1 * np.arange(21)
        assert np.max(np.abs(np.interp(sampled, times, values) - np.array(recorded))) <= 0.05 + 1e-6
        net.command("R", "save")
        saved = json.loads((tmp_path / "Sequences" / "sequence.json").read_text())
        assert saved["sequences"][0]["name"] == "Sequence A" and len(saved["sequences"][0]["channels"][0]) == len(keys)
    finally:
        net.close()


def test_trig_plays_its_sequence_and_an_empty_one_is_an_error(tmp_path):
    sequences_file(tmp_path, ("A", [[[0, 0.1]]]), ("B", [[[0, 0.7], [0.2, 0.7]]]))
    extra = ('<module class="Constant" name="T" data="0 1"/>\n'
             '<connection source="T.OUTPUT" target="R.TRIG" delay="0"/>\n')
    net = recorder(tmp_path, 'smoothing_time="0" max_sequences="3"', extra=extra)
    try:
        net.step()
        assert net.output("R.PLAYING").tolist() == [0, 1, 0]
        assert net.output("R.OUTPUT")[0] == pytest.approx(0.7)
        net.command("R", "select", 2)
        net.command("R", "play")
        net.step()
        assert net.output("R.ERROR")[0] == 1
        assert any("sequence 2 ('Sequence 3') is empty" in m for _, _, _, m in net.log)
    finally:
        net.close()
