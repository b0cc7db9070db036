"""The numerical libraries' thread pools are limited while a run is in real time, and only
then."""
import os

import pytest
import threadpoolctl

import ikaros
from ikaros.kernel.threadpools import ThreadPools, default_threads, parse_setting

MODEL = """<group tick_duration="0.001"{settings}>
  <module class="Constant" name="C" data="1, 2"/>
  <module class="Scale" name="S" factor="2"/>
  <connection source="C.OUTPUT" target="S.INPUT"/>
</group>"""


def _blas_threads() -> list[int]:
    return [p["num_threads"] for p in threadpoolctl.threadpool_info()
            if p["user_api"] == "blas"]


def _run(tmp_path, settings, real_time):
    """The BLAS threads seen after each tick, and the thread-pool figures after the run."""
    path = tmp_path / "m.ikg"
    path.write_text(MODEL.format(settings=settings))
    with ikaros.load(str(path)) as net:
        seen = []
        net.controller.tick_hooks.append(lambda: seen.append(_blas_threads()))
        net.run(ticks=3, real_time=real_time)
        return seen, net.figures()["thread_pools"]


def test_the_default_leaves_a_core_for_everything_else():
    assert default_threads() == max(1, len(os.sched_getaffinity(0)) - 1)


def test_the_setting_is_read():
    assert parse_setting(None) is None
    assert parse_setting(" 3 ") == 3
    assert parse_setting("off") == 0
    with pytest.raises(ValueError, match='blas_threads="0" must be a whole number >= 1, or off'):
        parse_setting("0")


def test_real_time_limits_the_pools_and_gives_them_back(tmp_path):
    before = _blas_threads()
    assert before, "numpy's BLAS is loaded"
    threadpoolctl.threadpool_limits(limits=2)
    try:
        seen, figures = _run(tmp_path, ' blas_threads="1"', real_time=True)
        assert seen == [[1] * len(before)] * 3
        assert _blas_threads() == [2] * len(before)
        assert figures["limit"] == 1 and figures["realtime"] is False
    finally:
        threadpoolctl.threadpool_limits(limits=before[0])


def test_a_run_that_is_not_in_real_time_leaves_the_pools_alone(tmp_path):
    before = _blas_threads()
    seen, _ = _run(tmp_path, ' blas_threads="1"', real_time=False)
    assert seen == [before] * 3


def test_off_leaves_the_pools_alone_in_real_time(tmp_path):
    before = _blas_threads()
    seen, figures = _run(tmp_path, ' blas_threads="off"', real_time=True)
    assert seen == [before] * 3 and figures["limit"] is None


def test_the_pools_follow_the_mode_when_it_changes():
    pools = ThreadPools(1)
    before = _blas_threads()
    pools.set_realtime(True)
    assert _blas_threads() == [1] * len(before)
    assert pools.report()["pools"][0]["threads"] == 1
    pools.set_realtime(False)
    assert _blas_threads() == before


def test_opencv_threads_are_limited_in_real_time_and_given_back(tmp_path):
    cv2 = pytest.importorskip("cv2")
    before = cv2.getNumThreads()
    cv2.setNumThreads(2)
    try:
        path = tmp_path / "m.ikg"
        path.write_text(MODEL.format(settings=' blas_threads="1"'))
        with ikaros.load(str(path)) as net:
            seen = []
            net.controller.tick_hooks.append(lambda: seen.append(cv2.getNumThreads()))
            net.run(ticks=3, real_time=True)
            net.run(ticks=2)
            pools = net.figures()["thread_pools"]["pools"]
        assert seen == [1, 1, 1, 2, 2]
        assert {"api": "opencv", "library": "opencv", "threads": 2} in pools
    finally:
        cv2.setNumThreads(before)
