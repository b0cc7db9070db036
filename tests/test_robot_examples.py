"""The robot examples run headless against the simulators: the Epi head follows its target,
the whole Epi (head and arms, EpiServos, an Ikaros 3 file) follows its waves, the LUCS arm
follows its guarded sines, and the recorded arm motion is played back; every example with a
robot driver runs to its end in a batch run, also on a machine whose cores are busy."""
import glob
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np
import pytest

import ikaros

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.path.join(ROOT, "examples")


DRIVERS = ("Dynamixel", "SSC32", "Epuck", "FadeCandy", "Phidgets", "EpiServos", "DynamixelController",
           "HeadServos")
# each robot example and the files it needs beside it
ROBOT_EXAMPLES = {"epi.ikg": ["EpiHeadPose.py"], "lucs_arm.ikg": [], "arm_playback.ikg": ["arm_motion.00.dat"],
                  "epuck_obstacles.ikg": [], "epi_servos.ikg": []}


def copy(tmp_path, *names):
    for name in names:
        shutil.copy(os.path.join(EXAMPLES, name), tmp_path)
    return str(tmp_path / names[0])


def run_in_real_time(net, ticks, probe):
    """Step ``ticks`` ticks on the model's time base; ``probe()`` after each tick."""
    period = net.clock.tick_duration
    start = time.perf_counter()
    rows = []
    for k in range(ticks):
        net.step()
        rows.append(probe())
        delay = start + (k + 1) * period - time.perf_counter()
        if delay > 0:
            time.sleep(delay)
    return rows


def test_epi_head_follows_the_target_through_the_guard(tmp_path):
    net = ikaros.load(copy(tmp_path, "epi.ikg", "EpiHeadPose.py"))
    try:
        rows = run_in_real_time(net, 150, lambda: (net.output("Gaze.OUTPUT").copy(), net.output("Guard.OUTPUT").copy(),
                                                    net.output("Head.FEEDBACK_PRESENT_POSITION").copy()))
        for (_, guarded, _), (_, _, previous) in zip(rows[1:], rows):
            assert np.all(np.abs(guarded - previous) <= 1.5 + 1e-3)        # REFERENCE is last tick's position
        gaze = np.array([r[0] for r in rows])
        assert np.ptp(gaze[:, 0]) > 15 and np.ptp(gaze[:, 1]) > 10          # the target moves the head
        errors = [np.max(np.abs(g - p)) for g, _, p in rows[50:]]
        assert np.median(errors) < 2.0                                       # and the head keeps up
        pose = net.output("Pose.TRANSFORMS")
        assert pose.shape == (6, 16) and abs(pose[1, 11] - (0.693 + 0.077)) < 1e-6     # the tilt axis
    finally:
        net.close()


def test_the_whole_epi_follows_its_waves_in_simulation(tmp_path):
    """Head and arms move; every servo is within its top speed × tick of its goal's path and
    inside its limits (EpiServos's MinLimitPosition/MaxLimitPosition; the pupils have none)."""
    net = ikaros.load(copy(tmp_path, "epi_servos.ikg"))
    try:
        assert net.dialect == "3"
        low = np.array([122, 130, 161, 156, 0, 0, 53, 73, 87, 53, 70, 0, 53, 79, 88, 158, 70, 0, 9])
        high = np.array([237, 240, 202, 193, 360, 360, 281, 281, 263, 202, 342, 360, 281, 290, 264, 316, 343, 360, 343])
        rows = []
        for _ in range(200):
            net.step()
            rows.append((net.output("Pose.OUTPUT").copy(), net.output("Servos.PRESENT_POSITION").copy()))
        present = np.array([p for _, p in rows])
        assert np.all(present >= low - 1e-3) and np.all(present <= high + 1e-3)
        assert np.ptp(present[:, :4], axis=0).min() > 5 and np.ptp(present[:, 6:18], axis=0).min() > 5
        # the goal arrives through a delay of 1: each servo is where last tick's goal was
        errors = [np.max(np.abs(np.clip(g, low, high) - p)) for (g, _), (_, p) in zip(rows[20:], rows[21:])]
        assert np.max(errors) < 1e-3                         # the simulated servos keep up
    finally:
        net.close()


def test_lucs_arm_follows_its_guarded_sines(tmp_path):
    net = ikaros.load(copy(tmp_path, "lucs_arm.ikg"))
    try:
        rows = run_in_real_time(net, 100, lambda: (net.output("Guard.OUTPUT").copy(),
                                                   net.output("Arm.FEEDBACK_PRESENT_POSITION").copy()))
        for (guarded, _), (_, previous) in zip(rows[1:], rows):
            assert np.all(np.abs(guarded - previous) <= 2 + 1e-3)           # steps of at most 2 from the arm
        goals = np.array([g for g, _ in rows])
        assert np.ptp(goals[:, 0]) > 20
        assert np.median([np.max(np.abs(g - p)) for g, p in rows[10:]]) < 3.0
        assert net.output("Arm.ERRORS").sum() == 0
    finally:
        net.close()


def test_the_recorded_arm_motion_is_played_back(tmp_path):
    net = ikaros.load(copy(tmp_path, "arm_playback.ikg", "arm_motion.00.dat"))
    try:
        assert net.output("Recorder.LENGTHS")[0] == 5
        rows = run_in_real_time(net, 150, lambda: net.output("Arm.FEEDBACK_PRESENT_POSITION").copy())
        pan = np.array([r[0] for r in rows])
        first_peak, first_dip = int(np.argmax(pan[:75])), int(np.argmin(pan[40:110])) + 40
        assert pan[first_peak] > 212 and 35 <= first_peak <= 65            # keyframe 220 at 1 s (tick 50)
        assert pan[first_dip] < 158 and 85 <= first_dip <= 115             # keyframe 150 at 2 s (tick 100)
    finally:
        net.close()


def test_every_example_with_a_robot_driver_is_run_here():
    pattern = re.compile(r'class="(' + "|".join(DRIVERS) + ')"')
    with_drivers = {os.path.basename(p) for p in glob.glob(os.path.join(EXAMPLES, "*.ikg"))
                    if pattern.search(open(p, encoding="utf-8").read())}
    assert with_drivers == set(ROBOT_EXAMPLES)


def run_batch(tmp_path, name: str, ticks: int) -> subprocess.CompletedProcess:
    """``ikaros -b -s TICKS`` on a copy of the example (and its files) in ``tmp_path``."""
    path = copy(tmp_path, name, *ROBOT_EXAMPLES[name])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in [ROOT, os.environ.get("PYTHONPATH")] if p))
    return subprocess.run([sys.executable, "-m", "ikaros", "-b", "-s", str(ticks), path], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=180)


@pytest.mark.parametrize("name", sorted(ROBOT_EXAMPLES))
def test_each_robot_example_runs_headless_to_its_end(tmp_path, name):
    result = run_batch(tmp_path, name, 50)
    assert result.returncode == 0, result.stderr
    assert "error" not in result.stderr.lower(), result.stderr


@pytest.mark.slow
def test_the_robot_examples_run_to_the_end_while_both_cores_are_busy(tmp_path):
    """Two busy loops (one a core on the 2-core test machine) while each example runs 50
    ticks: lost or late status packets are asked for again and counted, not fatal."""
    hogs = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(2)]
    try:
        for name in sorted(ROBOT_EXAMPLES):
            folder = tmp_path / name.split(".")[0]
            folder.mkdir()
            result = run_batch(folder, name, 50)
            assert result.returncode == 0, f"{name}: {result.stderr}"
            assert "error" not in result.stderr.lower(), f"{name}: {result.stderr}"
    finally:
        for hog in hogs:
            hog.kill()
            hog.wait()
