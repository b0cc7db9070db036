"""Waiting for real-time deadlines."""
import time

import pytest

from ikaros.kernel.timing import Waiter


def test_wait_until_returns_at_the_deadline_not_before():
    waiter = Waiter()
    for delay in (0.0, 0.0001, 0.003):
        deadline = time.perf_counter() + delay
        waited = waiter.wait_until(deadline)
        assert time.perf_counter() >= deadline and waited >= delay - 0.0001


def test_the_margin_follows_late_wake_ups():
    waiter = Waiter(margin=0.0005)
    waiter._woke(0.001)                       # 1 ms late: the margin rises at once
    assert waiter.margin == pytest.approx(0.00105)
    waiter._woke(0.0)                         # prompt: it falls 1 % of the way to 50 us
    assert waiter.margin == pytest.approx(0.00105 - 0.01 * (0.00105 - 0.00005))
    waiter._woke(0.05)                        # a 50 ms stall: capped
    assert waiter.margin == Waiter.MAX_MARGIN
    for _ in range(2000):
        waiter._woke(0.0)
    assert waiter.margin == Waiter.MIN_MARGIN


def test_a_margin_too_large_to_sleep_is_tried_smaller():
    waiter = Waiter(margin=0.002)
    waiter.wait_until(time.perf_counter() + 0.001)     # no sleep taken: spins
    assert waiter.margin == pytest.approx(0.002 * Waiter.UNUSED_FALL)
