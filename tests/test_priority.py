"""Scheduling priority of real-time runs: asked for, granted where the process may, refused
with a warning that says what to do where it may not, and nothing changed unasked."""
import ctypes
import ctypes.util
import json
import os
import resource
import subprocess
import sys
import threading

import pytest

import ikaros
from ikaros import priority
from ikaros.priority import PriorityError, PriorityRequest

MODEL = """<group tick_duration="0.001"{settings}>
  <module class="Constant" name="C" data="1, 2"/>
  <module class="Scale" name="S" factor="2"/>
  <connection source="C.OUTPUT" target="S.INPUT"/>
</group>"""

# Runs the model 20 ticks in real time in this (the main) thread, then prints what the tick
# thread was given, as the kernel reports it and as Linux has it.
CHILD = """
import json, os, sys, ikaros
net = ikaros.load(sys.argv[1])
net.run(ticks=20, real_time=True)
print("RESULT", json.dumps({"report": net.figures()["priority"],
                            "policy": os.sched_getscheduler(0),
                            "level": os.sched_getparam(0).sched_priority,
                            "nice": os.getpriority(os.PRIO_PROCESS, 0)}))
"""

CAP_IPC_LOCK, CAP_SYS_NICE = 14, 23      # linux/capability.h
PR_CAPBSET_DROP = 24                     # linux/prctl.h


def _without_permission():
    """In the child before exec: no CAP_SYS_NICE or CAP_IPC_LOCK (gone from the bounding set,
    so the program exec'd does not have them even as root), no real-time priority and no
    lower nice allowed by the limits."""
    libc = ctypes.CDLL(ctypes.util.find_library("c"), use_errno=True)
    for cap in (CAP_SYS_NICE, CAP_IPC_LOCK):
        if libc.prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0:
            raise OSError(ctypes.get_errno(), "prctl(PR_CAPBSET_DROP)")
    resource.setrlimit(resource.RLIMIT_RTPRIO, (0, 0))
    resource.setrlimit(resource.RLIMIT_NICE, (0, 0))
    resource.setrlimit(resource.RLIMIT_MEMLOCK, (64 * 1024, 64 * 1024))


def _run_child(tmp_path, settings, preexec=None):
    model = tmp_path / "m.ikg"
    model.write_text(MODEL.format(settings=settings))
    done = subprocess.run([sys.executable, "-c", CHILD, str(model)], capture_output=True,
                          text=True, timeout=120, preexec_fn=preexec)
    assert done.returncode == 0, done.stderr
    line = [x for x in done.stdout.splitlines() if x.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT "):]), done.stdout + done.stderr


@pytest.fixture(autouse=True)
def _forget_the_request():
    yield
    priority.reset()


def test_the_settings_are_read():
    assert PriorityRequest.parse("fifo") == PriorityRequest("fifo", 40, None, True)
    assert PriorityRequest.parse("rr:80", lock_memory="no") == PriorityRequest("rr", 80)
    assert PriorityRequest.parse("nice") == PriorityRequest("nice", -10)
    assert PriorityRequest.parse("nice:5", cpus="0") == PriorityRequest("nice", 5, (0,))
    assert PriorityRequest.parse("off") is None
    assert PriorityRequest.parse(None) is None


@pytest.mark.parametrize("text, message", [
    ("fast", 'priority="fast" must be fifo, rr or nice'),
    ("fifo:100", 'priority="fifo:100": the level of fifo must be a whole number from 1 to 99'),
    ("nice:-21", 'the level of nice must be a whole number from -20 to 19'),
])
def test_a_bad_priority_is_refused_naming_it(text, message):
    with pytest.raises(PriorityError, match=message.replace("(", r"\(")):
        PriorityRequest.parse(text)


def test_cores_this_process_may_not_use_are_refused_at_load(tmp_path):
    allowed = ",".join(map(str, sorted(os.sched_getaffinity(0))))
    model = tmp_path / "m.ikg"
    model.write_text(MODEL.format(settings=' cpus="4095"'))
    with pytest.raises(ikaros.ModelError,
                       match=f'cpus="4095": this process may use the cores {allowed} only'):
        ikaros.load(str(model))


def test_a_run_that_does_not_ask_changes_nothing(tmp_path):
    model = tmp_path / "m.ikg"
    model.write_text(MODEL.format(settings=""))
    policy, nice = os.sched_getscheduler(0), os.getpriority(os.PRIO_PROCESS, 0)
    with ikaros.load(str(model)) as net:
        net.run(ticks=20, real_time=True)
        assert net.figures()["priority"] is None
    assert (os.sched_getscheduler(0), os.getpriority(os.PRIO_PROCESS, 0)) == (policy, nice)


@pytest.mark.skipif(os.geteuid() != 0, reason="granting SCHED_FIFO needs root here")
def test_a_real_time_policy_is_granted_to_the_tick_thread(tmp_path):
    got, printed = _run_child(tmp_path, ' priority="fifo:30"')
    assert (got["policy"], got["level"]) == (os.SCHED_FIFO, 30)
    assert got["report"] == {"requested": "fifo:30, memory locked",
                             "tick_thread": "SCHED_FIFO 30", "device_threads": [],
                             "background_threads": [], "cpus": None, "memory_locked": True,
                             "refused": []}
    assert "priority: tick thread SCHED_FIFO 30, memory locked" in printed


def test_a_refused_policy_is_a_warning_that_says_what_to_do(tmp_path):
    got, printed = _run_child(tmp_path, ' priority="fifo"', preexec=_without_permission)
    assert (got["policy"], got["nice"]) == (os.SCHED_OTHER, os.getpriority(os.PRIO_PROCESS, 0))
    report = got["report"]
    assert report["tick_thread"] == f"nice {got['nice']}"
    assert report["memory_locked"] is False
    memory, fifo, nice = report["refused"]
    assert fifo.startswith("SCHED_FIFO 40 for the tick thread: Operation not permitted; ")
    assert "setcap cap_sys_nice+ep" in fifo and "ulimit -r 99" in fifo
    assert nice.startswith(f"nice -10 for the tick thread: not permitted (it runs at nice "
                           f"{got['nice']}); ") and "ulimit -e 40" in nice
    assert memory.startswith("locking memory: ") and "ulimit -l unlimited" in memory
    for refusal in report["refused"]:
        assert f"warning: priority refused: {refusal}" in printed


def test_the_status_api_shows_the_request(tmp_path):
    from starlette.testclient import TestClient
    from ikaros.webui.server import create_app
    nice = os.getpriority(os.PRIO_PROCESS, threading.get_native_id())
    model = tmp_path / "m.ikg"
    model.write_text(MODEL.format(settings=f' priority="nice:{nice}" cpus="0"'))
    cores = os.sched_getaffinity(0)
    try:
        with ikaros.load(str(model)) as net:
            net.run(ticks=3, real_time=True)
            with TestClient(create_app(net)) as client:
                status = client.get("/api/status").json()
    finally:
        os.sched_setaffinity(0, cores)
    assert status["priority"] == {"requested": f"nice:{nice}, cores 0",
                                  "tick_thread": f"nice {nice}", "device_threads": [],
                                  "background_threads": [], "cpus": [0],
                                  "memory_locked": None, "refused": []}


def test_device_and_background_threads_started_before_the_request_get_it_then():
    release, ready = threading.Event(), threading.Barrier(3)
    seen = {}

    def device():
        priority.device_thread()
        ready.wait()
        release.wait()
        seen["device"] = os.getpriority(os.PRIO_PROCESS, threading.get_native_id())

    def background():
        priority.background_thread()
        ready.wait()
        release.wait()
        seen["background"] = os.getpriority(os.PRIO_PROCESS, threading.get_native_id())
    threads = [threading.Thread(target=device), threading.Thread(target=background)]
    for t in threads:
        t.start()
    ready.wait()
    nice = os.getpriority(os.PRIO_PROCESS, threading.get_native_id())
    priority.configure(PriorityRequest("nice", nice))
    release.set()
    for t in threads:
        t.join(10)
    assert seen == {"device": nice, "background": max(nice, priority.BACKGROUND_NICE)}


def _below_tick_thread_of(request: PriorityRequest, before: bool) -> tuple:
    """(policy, level, nice) of a thread that calls ``below_tick_thread`` before or after
    ``request`` is made, as Linux has it."""
    registered, release, seen = threading.Event(), threading.Event(), []

    def helper():
        priority.below_tick_thread()
        registered.set()
        release.wait(10)
        seen.append((os.sched_getscheduler(0) & ~os.SCHED_RESET_ON_FORK,
                     os.sched_getparam(0).sched_priority,
                     os.getpriority(os.PRIO_PROCESS, threading.get_native_id())))
    if not before:
        priority.configure(request)
    thread = threading.Thread(target=helper)
    thread.start()
    registered.wait(10)
    if before:
        priority.configure(request)
    release.set()
    thread.join(10)
    return seen[0]


@pytest.mark.skipif(os.geteuid() != 0, reason="granting SCHED_FIFO needs root here")
@pytest.mark.parametrize("before", [True, False])
def test_a_below_tick_thread_runs_under_the_real_time_policy_below_the_tick(before):
    nice = os.getpriority(os.PRIO_PROCESS, threading.get_native_id())     # inherited
    assert _below_tick_thread_of(PriorityRequest("fifo", 30), before) == \
        (os.SCHED_FIFO, 30 - priority.BELOW_TICK, nice)
    priority.reset()
    assert _below_tick_thread_of(PriorityRequest("rr", 5), before) == (os.SCHED_RR, 1, nice)


@pytest.mark.skipif(os.geteuid() != 0, reason="granting SCHED_FIFO needs root here")
def test_a_below_tick_thread_is_listed_with_the_background_threads_and_not_inherited():
    priority.configure(PriorityRequest("fifo", 30))
    registered, release, started = threading.Event(), threading.Event(), []

    def child():
        started.append(os.sched_getscheduler(0))

    def helper():
        priority.below_tick_thread()
        thread = threading.Thread(target=child)
        thread.start()
        thread.join(10)
        registered.set()
        release.wait(10)
    thread = threading.Thread(target=helper)
    thread.start()
    registered.wait(10)
    try:
        assert priority.report()["background_threads"] == \
            [f"SCHED_FIFO {30 - priority.BELOW_TICK}"]
        assert started == [os.SCHED_OTHER]     # a thread it starts runs at the normal policy
    finally:
        release.set()
        thread.join(10)


@pytest.mark.parametrize("request_", [PriorityRequest("fifo", 1), PriorityRequest("nice", 0),
                                      PriorityRequest(None, 0, lock_memory=True)])
def test_a_below_tick_thread_is_a_background_thread_when_the_tick_is_not_above_it(request_):
    # fifo:1 has no level below it; nice and no policy: nothing real-time to run below
    nice = max(os.getpriority(os.PRIO_PROCESS, threading.get_native_id()),
               priority.BACKGROUND_NICE)
    for before in (True, False):
        priority.reset()
        assert _below_tick_thread_of(request_, before) == (os.SCHED_OTHER, 0, nice)
