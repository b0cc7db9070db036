"""The short GIL switch interval while helper threads work (kernel/switching.py)."""
import sys

import pytest

from ikaros.kernel import switching

SHORT = pytest.approx(switching.SWITCH_INTERVAL)    # kept in whole microseconds


def test_the_interval_is_short_while_any_helper_works_and_restored_after():
    before = sys.getswitchinterval()
    sys.setswitchinterval(0.004)
    try:
        switching.shorten()
        switching.shorten()
        short = sys.getswitchinterval()
        switching.restore()
        one_left = sys.getswitchinterval()
        switching.restore()
        assert (short, one_left, sys.getswitchinterval()) == (SHORT, SHORT, 0.004)
    finally:
        sys.setswitchinterval(before)


def test_a_recording_shortens_the_interval_until_it_is_closed(tmp_path):
    pytest.importorskip("h5py")
    from ikaros.testing import load_body
    net = load_body(tmp_path, '<module class="Constant" name="C" data="1 2"/>')
    before = sys.getswitchinterval()
    recorder = net.record(str(tmp_path / "run.h5"))
    assert sys.getswitchinterval() == SHORT
    net.run(ticks=3)
    recorder.close()
    assert sys.getswitchinterval() == before
    net.close()
