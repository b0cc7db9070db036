"""safety.shut_down: the end of a driver's run tries every step, in order."""
import pytest

from ikaros.hardware import DeviceError, safety


class Part:
    def __init__(self, log, name):
        self.log, self.name = log, name

    def close(self):
        self.log.append(f"{self.name} closed")

    def stop(self):
        self.log.append(f"{self.name} stopped")


def test_a_device_that_cannot_be_made_safe_is_reported_and_still_closed():
    log = []

    def make_safe():
        log.append("make safe")
        raise DeviceError("no answer")
    key = safety.on_exit("the test device", lambda: log.append("at exit"))
    watchdog = safety.Watchdog(60, lambda: log.append("watchdog"))
    safety.shut_down(watchdog, make_safe, key, Part(log, "device"), Part(log, "simulator"),
                     lambda error: log.append(f"reported: {error}"))
    assert log == ["make safe", "reported: no answer", "device closed", "simulator stopped"]
    assert not watchdog._thread.is_alive()
    assert key not in safety._at_exit


def test_other_failures_go_on_after_the_device_is_closed():
    log = []

    def make_safe():
        raise RuntimeError("driver bug")
    with pytest.raises(RuntimeError, match="driver bug"):
        safety.shut_down(None, make_safe, None, Part(log, "device"), None, log.append)
    assert log == ["device closed"]


def test_without_an_open_device_nothing_is_made_safe():
    log = []
    safety.shut_down(None, lambda: log.append("make safe"), None, None, Part(log, "simulator"),
                     log.append)
    assert log == ["simulator stopped"]
