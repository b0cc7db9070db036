"""Tests of TheEyeTribe against a simulated tracker server on 127.0.0.1."""
import socket
import time

import pytest

from ikaros.errors import ModelError
from ikaros.hardware.eyetribe import HEARTBEAT, MAX_PENDING, PUSH_REQUEST, messages
from ikaros.hardware.eyetribe_sim import SimulatedEyeTribe, frame
from ikaros.module import WARNING
from ikaros.testing import load_body as load, step_until


@pytest.fixture
def tracker():
    sim = SimulatedEyeTribe()
    yield sim
    sim.close()


def test_frames_reach_the_outputs(tmp_path, tracker):
    net = load(tmp_path, f'<module class="TheEyeTribe" name="E" port="{tracker.port}"/>')
    try:
        net.step()
        assert net.output("E.RAW").tolist() == [0, 0]
        tracker.push(frame(1500, 640, 360, fix=True, pupil=21.5))
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 1500)
        assert net.output("E.FIX").tolist() == [1]
        assert net.output("E.RAW").tolist() == [640, 360]
        assert net.output("E.AVG").tolist() == [640, 360]
        assert net.output("E.LEFT_EYE_RAW").tolist() == [630, 360]
        assert net.output("E.RIGHT_AVG_RAW").tolist() == [650, 360]
        assert net.output("E.LEFT_PUPIL_SIZE").tolist() == [21.5]
        assert net.output("E.RIGHT_PUPIL_CENTER").tolist() == pytest.approx([0.51, 0.5])
        tracker.push(frame(1533, 100, 50))
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 1533)
        assert net.output("E.FIX").tolist() == [0]
        assert net.output("E.RAW").tolist() == [100, 50]
        time.sleep(0.6)
        assert tracker.requests[0] == PUSH_REQUEST
        assert tracker.requests.count(HEARTBEAT) >= 2           # every 250 ms
    finally:
        net.close()


def test_a_lost_server_is_reported_and_reconnected(tmp_path, tracker):
    net = load(tmp_path, f'<module class="TheEyeTribe" name="E" port="{tracker.port}"/>')
    try:
        tracker.push(frame(10, 1, 2))
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 10)
        tracker.drop()
        step_until(net, lambda: any("lost the Eye Tribe server" in m
                                    for _, lv, _, m in net.log if lv == WARNING))
        assert net.output("E.RAW").tolist() == [1, 2]             # kept
        tracker.push(frame(20, 3, 4))                             # after the reconnection
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 20)
        assert net.output("E.RAW").tolist() == [3, 4]
    finally:
        net.close()


def test_no_server_is_a_load_error(tmp_path):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    with pytest.raises(ModelError, match=f"cannot reach the Eye Tribe server at "
                                         f"127.0.0.1:{port}"):
        load(tmp_path, f'<module class="TheEyeTribe" name="E" port="{port}"/>')


def test_messages_split_anywhere_are_put_together():
    text = '{"category": "heartbeat"}{"category":"tracker","values":{"frame":{"time":1}}}  {"ca'
    found, rest, skipped = messages(text)
    assert found == [{"category": "heartbeat"},
                     {"category": "tracker", "values": {"frame": {"time": 1}}}]
    assert rest == '{"ca'
    assert skipped == []


def test_text_that_is_no_json_is_skipped_and_reading_resumes_at_the_next_message():
    text = 'oops{"category": "heartbeat"}{bad json}{"a": "}{"}{"category": "heartbeat", "x": {'
    found, rest, skipped = messages(text)
    assert found == [{"category": "heartbeat"}, {"a": "}{"}]
    assert skipped == ["oops", "{bad json}"]
    assert rest == '{"category": "heartbeat", "x": {'
    found, rest, skipped = messages("{" * (MAX_PENDING + 10))         # the buffer is bounded
    assert (found, rest, len(skipped)) == ([], "", 1)


def test_a_bad_message_is_reported_and_later_frames_still_arrive(tmp_path, tracker):
    net = load(tmp_path, f'<module class="TheEyeTribe" name="E" port="{tracker.port}"/>')
    try:
        net.step()
        tracker.send_text("<html>502 Bad Gateway</html>\n{not: json}")
        tracker.push(frame(42, 5, 6))
        step_until(net, lambda: net.output("E.TIME_STAMP")[0] == 42)
        assert net.output("E.RAW").tolist() == [5, 6]
        warnings = [m for _, lv, _, m in net.log if lv == WARNING]
        assert any(f"127.0.0.1:{tracker.port} that is not JSON: '<html>502 Bad Gateway</html>'" in m
                   for m in warnings)
        assert any("that is not JSON: '{not: json}'" in m for m in warnings)
    finally:
        net.close()
