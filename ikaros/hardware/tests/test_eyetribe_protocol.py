"""The Eye Tribe client's reading of the tracker's message stream: a message cut off costs that
message alone, with its warning, and the frames after it arrive at once (The Eye Tribe "API
Reference": JSON messages, each ended by a newline)."""
import json

from ikaros.hardware.eyetribe import EyeTribeClient, messages
from ikaros.hardware.eyetribe_sim import SimulatedEyeTribe, frame
from ikaros.module import WARNING
from ikaros.testing import load_body, step_until, wait_for

CUT = '{"category":"tracker","values":{"fr'


def line(message: dict) -> str:
    return json.dumps(message) + "\n"


def tracker_message(time_ms: int) -> dict:
    return {"category": "tracker", "statuscode": 200, "values": {"frame": frame(time_ms, 1, 2)}}


def test_a_message_cut_off_is_skipped_and_the_next_one_read_on_the_same_line():
    """The cut message's end and its newline are lost: the next message follows on its line."""
    found, rest, skipped = messages(CUT + line(tracker_message(10)) + line(tracker_message(11)))
    assert [m["values"]["frame"]["time"] for m in found] == [10, 11]
    assert (rest, skipped) == ("", [CUT])


def test_a_message_cut_off_before_its_newline_costs_that_message_alone():
    found, rest, skipped = messages(CUT + "\n" + line(tracker_message(12)))
    assert [m["values"]["frame"]["time"] for m in found] == [12]
    assert (rest, skipped) == ("", [CUT])


def test_a_cut_message_inside_a_string_and_a_bad_line_resynchronise_at_the_newline():
    text = '{"category":"tracker","values":{"frame":{"timestamp":"2024-01\n' + line(tracker_message(13)) \
        + "{not json at all\n" + line(tracker_message(14))
    found, rest, skipped = messages(text)
    assert [m["values"]["frame"]["time"] for m in found] == [13, 14]
    assert skipped == ['{"category":"tracker","values":{"frame":{"timestamp":"2024-01', "{not json at all"]


def test_a_message_not_yet_ended_is_kept_for_the_rest():
    found, rest, skipped = messages(line(tracker_message(15)) + CUT)
    assert len(found) == 1 and rest == CUT and skipped == []


def test_the_client_reads_the_frames_after_a_cut_message_at_once():
    sim = SimulatedEyeTribe()
    client = EyeTribeClient("127.0.0.1", sim.port)
    try:
        sim.push(frame(1, 5, 5))
        assert wait_for(lambda: client.newest()[1] == 1)
        sim.send_text(CUT)
        sim.push(frame(2, 6, 6))
        assert wait_for(lambda: client.newest()[1] == 2)        # the next frame, not 64 KiB later
        assert client.newest()[0]["time"] == 2
        assert client.take_skipped() == [CUT]
    finally:
        client.close()
        sim.close()


def test_the_eye_tribe_module_warns_once_and_its_frames_resume(tmp_path):
    sim = SimulatedEyeTribe()
    net = load_body(tmp_path, f'<module class="TheEyeTribe" name="E" port="{sim.port}"/>')
    try:
        sim.push(frame(100, 1, 2))
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 100)
        sim.send_text(CUT)
        for k in range(1, 4):
            sim.push(frame(100 + k, 1 + k, 2))
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 103)
        assert net.output("E.RAW").tolist() == [4, 2]
        warnings = [m for _, level, _, m in net.log if level == WARNING]
        assert len(warnings) == 1 and CUT in warnings[0]
    finally:
        net.close()
        sim.close()
