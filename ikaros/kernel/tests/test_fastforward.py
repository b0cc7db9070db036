"""Fast-forward: play with the tick hooks (the web UI's copies) run at most ten times a
second, and once more when it pauses, so the last tick is seen."""
from __future__ import annotations

import time

import ikaros
from ikaros.kernel.control import FASTFORWARD, FASTFORWARD_HOOK_INTERVAL, PAUSE


def test_fast_forward_runs_the_hooks_rarely_and_shows_the_last_tick(tmp_path):
    (tmp_path / "m.ikg").write_text('<group name="G"><module class="Constant" name="C" '
                                    'data="1"/></group>')
    net = ikaros.load(str(tmp_path / "m.ikg"))
    seen = []
    ctrl = net.controller
    ctrl.tick_hooks.append(lambda: seen.append(net.tick))
    ctrl.start(FASTFORWARD)
    time.sleep(0.55)
    ctrl.set_state(PAUSE)
    deadline = time.monotonic() + 5
    while (not seen or seen[-1] != net.tick) and time.monotonic() < deadline:
        time.sleep(0.01)
    ctrl.stop()
    ctrl.join(5)
    net.close()
    assert net.tick > 100                       # it ran ticks as fast as it could
    assert 1 <= len(seen) <= 0.55 / FASTFORWARD_HOOK_INTERVAL + 3
    assert seen[-1] == net.tick                 # paused: the hooks saw the last tick
