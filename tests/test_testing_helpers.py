"""ikaros.testing.step_until: steps one or several networks until a condition holds."""
import pytest

from ikaros.testing import load_body, step_until, wait_for

TICKER = '<module class="Constant" name="C" data="1"/>'


def test_step_until_steps_every_network_until_the_condition_holds(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    first, second = load_body(tmp_path / "a", TICKER), load_body(tmp_path / "b", TICKER)
    try:
        step_until(first, lambda: first.tick == 3, pause=0)
        assert first.tick == 3
        step_until([first, second], lambda: second.tick == 2, pause=0)
        assert (first.tick, second.tick) == (5, 2)
    finally:
        first.close()
        second.close()


def test_step_until_fails_after_its_time(tmp_path):
    net = load_body(tmp_path, TICKER)
    try:
        with pytest.raises(AssertionError, match="timed out after 0.05 s"):
            step_until(net, lambda: False, 0.05)
    finally:
        net.close()


def test_wait_for_says_whether_the_condition_came_in_time():
    answers = iter([False, False, True])
    assert wait_for(lambda: next(answers), 1.0, pause=0) is True
    assert wait_for(lambda: 0, 0.02) is False
