"""The controller's background loop: a stop tick of 0, and a long real-time wait that a
change of state or a request ends at once."""
import time

import ikaros
from ikaros.kernel.control import PAUSE, REALTIME

MODEL = '<group name="M" tick_duration="{d}"><module class="Constant" name="C" data="1"/></group>'


def _load(tmp_path, duration):
    (tmp_path / "m.ikg").write_text(MODEL.format(d=duration))
    return ikaros.load(str(tmp_path / "m.ikg"))


def _wait(condition, seconds=5.0):
    deadline = time.monotonic() + seconds
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.01)
    return condition()


def test_a_stop_tick_of_0_pauses_before_the_first_tick(tmp_path):
    net = _load(tmp_path, 0.01)
    net.stop_tick = 0
    c = net.controller
    try:
        c.start(REALTIME)
        time.sleep(0.3)
        assert (net.tick, c.state) == (0, PAUSE)
    finally:
        c.stop()
        c.join(5)
        net.close()


def test_a_long_real_time_wait_ends_at_a_stop_or_a_request(tmp_path):
    net = _load(tmp_path, 30)        # the next tick is due in 30 s
    c = net.controller
    try:
        c.start(REALTIME)
        assert _wait(lambda: net.tick == 1)
        start = time.monotonic()
        assert c.call(lambda: net.tick) == 1          # answered between ticks, at once
        assert time.monotonic() - start < 2
        start = time.monotonic()
        c.stop()
        c.join(5)
        assert not c.running and time.monotonic() - start < 2
        assert net.tick == 1                          # no tick ran early
    finally:
        c.stop()
        c.join(5)
        net.close()
