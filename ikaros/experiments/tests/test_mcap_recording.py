"""MCAP recordings: read back by the mcap reader and decoded by rosbags (an independent ROS 2
implementation), tick for tick equal to the model's outputs."""
import numpy as np
import pytest
from mcap.reader import make_reader
from rosbags.typesys import Stores, get_typestore, get_types_from_msg

import ikaros

MODEL = """<group tick_duration="0.01">
  <module class="FunctionGenerator" name="Wave" type="sin" frequency="0.1"/>
  <module class="Constant" name="Grid" data="1, 2, 3; 4, 5, 6"/>
  <module class="Scale" name="Twice" factor="2"/>
  <connection source="Wave.OUTPUT" target="Twice.INPUT"/>
</group>"""


def _run(tmp_path, ticks=25):
    model = tmp_path / "m.ikg"
    model.write_text(MODEL)
    seen = {}
    with ikaros.load(str(model)) as net:
        recording = net.record(str(tmp_path / "run.mcap"))
        for _ in range(ticks):
            net.run(ticks=1)
            for path in ("Wave.OUTPUT", "Grid.OUTPUT", "Twice.OUTPUT"):
                seen[(path, net.tick - 1)] = net.output(path)
        recording.close()
    return seen


def test_every_tick_of_every_output_is_a_ros_2_message(tmp_path):
    seen = _run(tmp_path)
    store = get_typestore(Stores.EMPTY)
    with open(tmp_path / "run.mcap", "rb") as f:
        reader = make_reader(f)
        summary = reader.get_summary()
        topics = {c.topic: summary.statistics.channel_message_counts[i]
                  for i, c in summary.channels.items()}
        assert topics == {"/ikaros/Wave/OUTPUT": 25, "/ikaros/Grid/OUTPUT": 25,
                          "/ikaros/Twice/OUTPUT": 25}
        got = {}
        for schema, channel, message in reader.iter_messages():
            assert (schema.name, schema.encoding, channel.message_encoding) == \
                ("std_msgs/msg/Float32MultiArray", "ros2msg", "cdr")
            if schema.name not in store.types:
                store.register(get_types_from_msg(schema.data.decode(), schema.name))
            decoded = store.deserialize_cdr(message.data, schema.name)
            path = channel.topic[len("/ikaros/"):].replace("/", ".")
            got[(path, message.sequence)] = decoded
            assert message.log_time - got.setdefault("t0", message.log_time) == \
                round(message.sequence * 0.01 * 1e9)
        attachments = [(a.name, a.data.decode()) for a in reader.iter_attachments()]
        metadata = {m.name: m.metadata for m in reader.iter_metadata()}
    got.pop("t0")
    assert sorted(got) == sorted(seen)
    for key, values in seen.items():
        decoded = got[key]
        np.testing.assert_array_equal(decoded.data, values.reshape(-1))
        assert [(d.size, d.stride) for d in decoded.layout.dim] == \
            ([(2, 6), (3, 3)] if key[0] == "Grid.OUTPUT" else [(1, 1)])
    assert attachments == [("model.ikg", MODEL)]
    assert metadata["parameters"]["Twice.factor"] == "2"
    assert metadata["ikaros"]["tick_duration"] == "0.01"


def test_a_failed_write_stops_the_run_and_leaves_no_file(tmp_path, monkeypatch):
    from mcap.writer import Writer
    written = []

    def fill_up(self, channel_id, log_time, data, publish_time, sequence=0):
        if len(written) == 30:
            raise OSError(28, "No space left on device")
        written.append(sequence)
    monkeypatch.setattr(Writer, "add_message", fill_up)
    model = tmp_path / "m.ikg"
    model.write_text(MODEL)
    path = tmp_path / "run.mcap"
    with ikaros.load(str(model)) as net:
        recording = net.record(str(path), flush_seconds=0)
        with pytest.raises(ikaros.RunError, match=r"writing the recording .*run\.mcap failed "
                                                  r"\(No space left on device\); it holds no "
                                                  r"ticks \(the file is removed\); the run "
                                                  r"stops"):
            net.run(ticks=10**7)      # ended by the failure, well before
        assert net.tick < 10**7
        with pytest.raises(OSError, match="No space left on device"):
            recording.close()
    assert not path.exists()
