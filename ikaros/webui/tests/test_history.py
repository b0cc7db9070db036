"""Every tick seen (issue 16, part 7): the per-tick history of buffers subscribed as
``history`` or ``events``, its envelope, and the frames that carry it over the WebSocket."""
from __future__ import annotations

import json
import time
import warnings

import numpy as np
import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.encoding import decode_frame  # noqa: E402
from ikaros.webui.history import Recorder, Ring, encode_events, encode_history, envelope  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

MODEL = """<?xml version="1.0"?>
<group name="T">
    <module class="FunctionGenerator" name="Ramp" type="ramp" frequency="0.01" />
    <module class="FunctionGenerator" name="Pulse" type="ticksquare" basetime="7" tickduty="1"
            size="3" />
</group>
"""


def test_ring_keeps_the_last_rows_with_their_ticks():
    src = np.zeros(2, np.float32)
    ring = Ring(src)
    for t in range(ring.capacity + 5):
        src[:] = [t, -t]
        ring.record(t + 1)
    ticks, rows = ring.since(ring.capacity + 5 - 3)
    assert ticks.tolist() == [ring.capacity + 3, ring.capacity + 4, ring.capacity + 5]
    assert rows[:, 0].tolist() == [ring.capacity + 2, ring.capacity + 3, ring.capacity + 4]
    ticks, _ = ring.since(-1)
    assert len(ticks) == ring.capacity and ticks[0] == 6


class _Net:
    tick = 0


def test_a_dropped_ring_is_taken_up_again_while_nothing_ran_since():
    """Issue 27, item 1: a page reloaded (or a view opened again) on a paused model gets
    the rows recorded before; a ring that missed ticks since it was dropped is not reused."""
    net, src = _Net(), np.zeros(1, np.float32)
    rec = Recorder(net, budget=1.0)
    rec.set_sources({"A.OUTPUT": src})
    for t in range(1, 51):
        net.tick = t
        src[0] = t
        rec.hook()
    rec.set_sources({})                         # the page went away
    rec.set_sources({"A.OUTPUT": src})          # and came back: nothing ran meanwhile
    ticks, rows, _ = rec.read({"A.OUTPUT": -1})["A.OUTPUT"]
    # (the first row is the value the buffer had when the ring began, at tick 0)
    assert ticks.tolist() == list(range(0, 51)) and rows[:, 0].tolist() == list(range(0, 51))
    rec.set_sources({})
    net.tick = 51                               # a tick ran while nobody subscribed
    rec.set_sources({"A.OUTPUT": src})          # a new ring: the value now, at tick 51
    assert rec.read({"A.OUTPUT": -1})["A.OUTPUT"][0].tolist() == [51]


def test_a_dropped_ring_that_missed_the_last_tick_is_taken_up_again_with_it():
    """Issue 37, item 6: under load the copying budget may leave the last tick before a
    pause out of a ring; a page reloaded then got a ring of the present tick alone."""
    net, src = _Net(), np.zeros(1, np.float32)
    rec = Recorder(net, budget=1.0)
    rec.set_sources({"A.OUTPUT": src})
    for t in range(1, 11):
        net.tick = t
        src[0] = t
        if t < 10:                              # tick 10: the budget was spent
            rec.hook()
    rec.set_sources({})                         # the page reloads, nothing ran meanwhile
    rec.set_sources({"A.OUTPUT": src})
    ticks, rows, _ = rec.read({"A.OUTPUT": -1})["A.OUTPUT"]
    assert ticks.tolist() == list(range(0, 11)) and rows[:, 0].tolist() == list(range(0, 11))


def test_envelope_keeps_every_peak():
    ticks = np.arange(1, 1001)
    rows = np.zeros((1000, 1), np.float32)
    rows[123, 0] = 5.0         # one-tick spike
    rows[700, 0] = -2.0
    col_ticks, env = envelope(ticks, rows, 100)
    assert env.shape == (100, 2, 1)
    assert col_ticks.tolist() == list(range(1, 1001, 10))
    assert env[12, 1, 0] == 5.0 and env[12, 0, 0] == 0.0
    assert env[70, 0, 0] == -2.0
    assert env[:, 1, 0].sum() == 5.0 and env[:, 0, 0].sum() == -2.0


def test_encode_history_samples_then_envelope_and_missed_ticks():
    ticks = np.array([11, 12, 14])
    rows = np.array([[1], [2], [4]], np.float32)
    payload, head = encode_history(ticks, rows, (1,), 10, 512)
    assert head == {"buffer_shape": [1], "missed": 1, "mode": "samples",
                    "ticks": [11, 12, 14], "shape": [3, 1]}
    assert np.frombuffer(payload, "<f4").tolist() == [1, 2, 4]
    payload, head = encode_history(ticks, rows, (1,), 10, 2)
    assert head["mode"] == "envelope" and head["shape"] == [2, 2, 1]
    assert np.frombuffer(payload, "<f4").tolist() == [1, 2, 4, 4]   # ticks 11-12 | 14


def test_encode_events_lists_every_event():
    ticks = np.arange(100, 110)
    rows = np.zeros((10, 3), np.float32)
    rows[0, 2] = rows[5, 0] = rows[5, 1] = rows[9, 2] = 1
    payload, head = encode_events(ticks, rows, (3,), 99)
    assert head["first_tick"] == 100 and head["last_tick"] == 109 and head["missed"] == 0
    pairs = np.frombuffer(payload, "<f4").reshape(-1, 2).tolist()
    assert pairs == [[0, 2], [5, 0], [5, 1], [9, 2]]


def test_recorder_stays_within_its_budget():
    class Net:
        tick = 1
    arrays = {f"A{i}": np.zeros(1, np.float32) for i in range(50)}
    rec = Recorder(Net(), budget=0.0)      # no time at all: one ring per tick
    rec.set_sources(arrays)
    # each ring starts with the value its buffer has now
    assert [r.ticks[0] for r in rec.rings.values()] == [1] * 50
    counts = lambda: {p: r.count for p, r in rec.rings.items()}
    Net.tick = 2
    rec.hook()
    assert sum(counts().values()) == 51 and rec.skipped == 49
    rec.hook()
    assert sum(counts().values()) == 52    # the next ring's turn
    rec.set_sources(arrays, events={"A7", "A9"})            # event buffers: every tick
    before = counts()
    Net.tick = 3
    rec.hook()
    grown = {p for p, n in counts().items() if n > before[p]}
    assert {"A7", "A9"} <= grown and len(grown) == 3        # A7, A9 and one in its turn


@pytest.fixture
def net(tmp_path):
    path = tmp_path / "t.ikg"
    path.write_text(MODEL)
    n = ikaros.load(str(path))
    n.log_level = WARNING
    yield n
    n.controller.stop()
    n.controller.join(5)
    n.close()


def _frame(ws):
    while True:
        m = ws.receive()
        if m.get("bytes") is not None:
            return decode_frame(m["bytes"])


def _wait(predicate, timeout=10.0):
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.005)
    return True


def test_frames_carry_every_tick_since_the_last_frame(net):
    """Played between two frames, 300 ticks of a ramp arrive as 300 samples (points 512),
    then as a 50-column envelope (points 50); the ticksquare pulses arrive as events,
    every one of them."""
    with TestClient(create_app(net)) as c, c.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "Ramp.OUTPUT", "format": "history"},
            {"path": "Pulse.OUTPUT", "format": "events"}]})
        ws.send_json({"type": "ready"})
        header, _ = _frame(ws)
        assert header["tick"] == 0
        expected = {}
        for _ in range(300):
            c.post("/api/control", json={"state": "step"})
            assert _wait(lambda: net.controller.state == "pause")
            expected[net.tick] = float(net.buffer_array("Ramp.OUTPUT")[0])
        ws.send_json({"type": "ready"})
        header, data = _frame(ws)
        assert header["tick"] == 300
        ramp, pulse = header["buffers"]
        assert ramp["mode"] == "samples" and ramp["missed"] == 0
        assert ramp["ticks"] == list(range(1, 301))
        assert data["Ramp.OUTPUT"][:, 0].tolist() == pytest.approx(
            [expected[t] for t in range(1, 301)])
        pairs = data["Pulse.OUTPUT"].reshape(-1, 2)
        ticks = (pairs[:, 0] + pulse["first_tick"]).astype(int)
        # ticksquare is 1 on the first tick of every 7 (tick t - 1 = 0, 7, 14, ...), in
        # all three elements
        want = [(t, e) for t in range(1, 301) if (t - 1) % 7 == 0 for e in range(3)]
        assert list(zip(ticks.tolist(), pairs[:, 1].astype(int).tolist())) == want

        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "Ramp.OUTPUT", "format": "history", "points": 50}]})
        ws.send_json({"type": "ready"})
        header, data = _frame(ws)       # a new subscription starts from the ring's start
        (ramp,) = header["buffers"]
        assert ramp["mode"] == "envelope" and ramp["shape"] == [50, 2, 1]
        env = data["Ramp.OUTPUT"][:, :, 0]
        values = np.array([expected[t] for t in range(1, 301)], np.float32)
        assert env[:, 0].tolist() == pytest.approx(values.reshape(50, 6).min(1).tolist())
        assert env[:, 1].tolist() == pytest.approx(values.reshape(50, 6).max(1).tolist())


def test_a_subscription_gets_only_the_latest_ticks_it_shows(net):
    """Issue 37, item 6: a plot that shows 20 ticks, subscribed (a page reloaded) after 100
    ticks, gets those 20 as samples, up to the current tick, not an envelope of all 100."""
    with TestClient(create_app(net)) as c, c.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "Ramp.OUTPUT", "format": "history", "points": 10}]})
        ws.send_json({"type": "ready"})
        _frame(ws)
        expected = {}
        for _ in range(100):
            c.post("/api/control", json={"state": "step"})
            assert _wait(lambda: net.controller.state == "pause")
            expected[net.tick] = float(net.buffer_array("Ramp.OUTPUT")[0])
        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "Ramp.OUTPUT", "format": "history", "points": 20, "ticks": 20}]})
        ws.send_json({"type": "ready"})
        header, data = _frame(ws)
        (ramp,) = header["buffers"]
        assert ramp["mode"] == "samples" and ramp["ticks"] == list(range(81, 101))
        assert data["Ramp.OUTPUT"][:, 0].tolist() == pytest.approx(
            [expected[t] for t in range(81, 101)])


def test_ticks_are_checked(net):
    with TestClient(create_app(net)) as c, c.websocket_connect("/api/ws") as ws:
        for bad in ({"path": "Ramp.OUTPUT", "format": "raw", "ticks": 5},
                    {"path": "Ramp.OUTPUT", "format": "history", "ticks": 0},
                    {"path": "Ramp.OUTPUT", "format": "history", "ticks": 1 << 20},
                    {"path": "Ramp.OUTPUT", "format": "history", "ticks": True}):
            ws.send_json({"type": "subscribe", "buffers": [bad]})
            while True:
                msg = json.loads(ws.receive()["text"])
                if msg["type"] == "error":
                    break
            assert '"ticks"' in msg["error"]


def test_points_are_checked(net):
    with TestClient(create_app(net)) as c, c.websocket_connect("/api/ws") as ws:
        for bad in ({"path": "Ramp.OUTPUT", "format": "raw", "points": 5},
                    {"path": "Ramp.OUTPUT", "format": "history", "points": 0},
                    {"path": "Ramp.OUTPUT", "format": "history", "points": "5"}):
            ws.send_json({"type": "subscribe", "buffers": [bad]})
            while True:
                msg = json.loads(ws.receive()["text"])
                if msg["type"] == "error":
                    break
            assert '"points"' in msg["error"]


def test_a_frame_replaced_before_it_was_sent_loses_no_tick():
    """Two frames built for one client before the first was sent (two "ready"s in
    flight): the second carries the first one's ticks too."""
    from ikaros.webui.snapshot import Client, Hub, Plan, Snapshot
    src = np.zeros(1, np.float32)
    plan = Plan({"A.OUTPUT": src}, 1)
    ring = Ring(src)
    c = Client(ws=None)
    c.subs = [("A.OUTPUT", "events")]

    def frame_at(tick):
        src[:] = 1
        ring.record(tick)
        snap = Snapshot(plan, tick, 0.0)
        snap.history = {"A.OUTPUT": (*ring.since(-1), (1,))}
        Hub._send_frame(c, snap, {})

    frame_at(1)
    frame_at(2)                                  # the frame of tick 1 was never sent
    header, data = decode_frame(c.frame)
    b = header["buffers"][0]
    assert (data["A.OUTPUT"][:, 0] + b["first_tick"]).tolist() == [1, 2]
    c.frame = None                               # sent
    frame_at(3)
    header, data = decode_frame(c.frame)
    assert (data["A.OUTPUT"][:, 0] + header["buffers"][0]["first_tick"]).tolist() == [3]


def test_a_snapshot_read_before_a_new_subscribe_is_not_sent_under_it():
    """Issue 27, item 1: history rows read for a client's old subscription lack what a new
    subscribe asks for (the whole ring again); that snapshot is not sent to it."""
    from ikaros.webui.snapshot import Client, Hub, Plan, Snapshot
    c = Client(ws=None)
    c.subs = [("A.OUTPUT", "history")]
    snap = Snapshot(Plan({}, 0), tick=700, time_=7.0)
    snap.history = {"A.OUTPUT": (np.arange(650, 701), np.zeros((51, 1), np.float32), (1,))}
    snap.history_since = {"A.OUTPUT": 649}
    c.seen = {"A.OUTPUT": 649}                  # what the client had when it was read
    assert Hub._history_covers(c, snap)
    c.seen = {}                                 # a subscribe came meanwhile
    assert not Hub._history_covers(c, snap)
