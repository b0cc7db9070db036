"""Tests of the Ikaros 2 PlanarArm: the forward kinematics match the formula, the motion rule
and the limits are those of the golden files (golden-v2 PlanarArm), the random targets are
the C library's rand(), and the targets follow their paths."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load

L = (0.35, 0.25, 0.20)


def joints(a0, a1, a2):
    """The formula, written out: angles from straight up, clockwise, relative."""
    x0, y0 = 0.5, 0.0
    x1, y1 = x0 + L[0] * math.sin(a0), y0 + L[0] * math.cos(a0)
    x2, y2 = x1 + L[1] * math.sin(a0 + a1), y1 + L[1] * math.cos(a0 + a1)
    x3, y3 = x2 + L[2] * math.sin(a0 + a1 + a2), y2 + L[2] * math.cos(a0 + a1 + a2)
    return np.array([[x0, y0], [x1, y1], [x2, y2], [x3, y3]])


def arm(tmp_path, angles="0 0 0", **params):
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    return load(tmp_path, f'<module class="Constant" name="D" data="{angles}"/>'
                          f'<module class="PlanarArm" name="A" {attrs}/>'
                          '<connection source="D.OUTPUT" target="A.DESIRED_ANGLES" delay="0"/>')


def move(a, d, speed=0.1):
    """The Ikaros 2 motion rule as the golden files show it: a largest change of 1 rad or
    more moves speed times the change, a smaller one arrives at once; then the limits."""
    a, d = np.asarray(a, float), np.asarray(d, float)
    new = a + speed * (d - a) if np.abs(d - a).max() >= 1 else d.copy()
    return np.clip(new, [-2 * math.pi / 3, 0, 0], [2 * math.pi / 3, math.pi, math.pi])


def test_forward_kinematics_match_the_formula(tmp_path):
    net = arm(tmp_path, seed=1)
    try:
        j = net.output("A.JOINTS")
        assert j.shape == (4, 2)
        assert np.allclose(j, joints(0.4, 0.4, 0.4), atol=1e-6)             # start pose
        assert np.allclose(net.output("A.ANGLES"), [0.4, 0.4, 0.4])
        # each change is below 1 rad, so the arm arrives in one tick
        for a in [(0, 0, 0), (0.3, 0.5, 0.7), (-0.4, 1.2, 0.4), (-1.0, 1.5, 0.5),
                  (-0.8, 1.2, 0.4), (-0.2, 0.4, 1.2)]:
            target = net.output("A.TARGET").copy()
            net.set_parameter("D.data", " ".join(map(str, a)))
            net.step()
            assert np.allclose(net.output("A.ANGLES"), a, atol=1e-6), a
            assert np.allclose(net.output("A.JOINTS"), joints(*a), atol=1e-6), a
            assert np.allclose(net.output("A.HAND_POSITION"), joints(*a)[3], atol=1e-6)
            d = np.hypot(*(joints(*a)[3] - target))        # to the previous tick's target
            assert net.output("A.DISTANCE")[0] == pytest.approx(d, abs=1e-6)
    finally:
        net.close()


def test_joint_limits_and_the_frame(tmp_path):
    net = arm(tmp_path, angles="0 0 0")
    try:
        net.step()
        # elbow and wrist limits are 0..pi: -0.5 is clipped; 4 is 4 rad away, a step
        net.set_parameter("D.data", "0.2 -0.5 0.9")
        net.step()
        assert np.allclose(net.output("A.ANGLES"), [0.2, 0, 0.9], atol=1e-6)
        # a posture with the hand outside 0.01..0.99 is refused: the arm stays
        net.set_parameter("D.data", "0.9 0 0.9")        # a change of 0.7 to a hand at x > 0.99
        assert joints(0.9, 0, 0.9)[3][0] > 0.99
        net.step()
        assert np.allclose(net.output("A.ANGLES"), [0.2, 0, 0.9], atol=1e-6)
    finally:
        net.close()
    # the shoulder is limited to +-2 pi / 3: postures reached by changes below 1 rad
    net = arm(tmp_path, angles="0 0 0")
    try:
        for a in ("-0.3 0.9 0", "0.3 1.8 0.3", "1.2 2.7 1.2", "2.15 2.7 1.2"):
            net.set_parameter("D.data", a)
            net.step()
        a = net.output("A.ANGLES")
        assert np.allclose(a, [2 * math.pi / 3, 2.7, 1.2], atol=1e-6)
        assert np.allclose(net.output("A.JOINTS"), joints(*a), atol=1e-6)
    finally:
        net.close()


def test_large_changes_move_a_tenth_of_the_way_small_ones_arrive(tmp_path):
    # golden-v2 PlanarArm "vector": from 0.4 towards (0.5, -1, 2): the largest change is 1.6,
    # so 0.1 of it per tick; the elbow stops at 0; with the elbow at 0 the change -1 still
    # counts as large. Then a change below 1 arrives at once.
    net = arm(tmp_path, angles="0.5 -1 2")
    try:
        expected = np.array([0.4, 0.4, 0.4])
        for _ in range(12):
            net.step()
            expected = move(expected, [0.5, -1, 2])
            assert np.allclose(net.output("A.ANGLES"), expected, atol=1e-5)
        assert expected[1] == 0 and 1.4 < expected[2] < 2
        assert np.allclose(net.output("A.ANGLES")[:2], [0.5 - 0.1 * 0.9 ** 12, 0], atol=1e-5)
        net.set_parameter("D.data", "0.3 0.5 1.2")
        net.step()
        assert np.allclose(net.output("A.ANGLES"), [0.3, 0.5, 1.2], atol=1e-6)
    finally:
        net.close()


def test_speed_scales_the_steps(tmp_path):
    net = arm(tmp_path, angles="0.4 -1 2.4", speed=0.25)
    try:
        net.step()
        assert np.allclose(net.output("A.ANGLES"), [0.4, 0.05, 0.9], atol=1e-6)
    finally:
        net.close()


def test_unconnected_desired_angles_keep_the_arm_still(tmp_path):
    net = load(tmp_path, '<module class="PlanarArm" name="A" seed="3"/>')
    try:
        net.run(ticks=5)
        assert np.allclose(net.output("A.JOINTS"), joints(0.4, 0.4, 0.4), atol=1e-6)
    finally:
        net.close()


@pytest.mark.parametrize("kind", ["linear", "circular", "lisajous", "square"])
def test_target_paths(tmp_path, kind):
    net = arm(tmp_path, angles="0 0 0", target_behavior=kind, target_speed=0.3,
              target_range=0.2, target_size=0.5)
    try:
        previous = (0.0, 0.0)
        for tick in range(25):
            net.step()
            p = 0.3 * (tick + 1)
            s, c = 0.2 * math.sin(p), 0.2 * math.cos(p)
            expected = {"linear": (0.5 + s, 0.5),
                        "circular": (0.5 + s, 0.5 + c),
                        "lisajous": (0.5 + s, 0.5 + 0.2 * math.cos(0.3 * p)),
                        "square": (0.5 + s / (abs(s) + abs(c)) * 0.2,
                                   0.5 + c / (abs(s) + abs(c)) * 0.2)}[kind]
            assert np.allclose(net.output("A.TARGET"), expected, atol=1e-6), tick
            d = math.hypot(0.5 - previous[0], 0.8 - previous[1])   # hand at (0.5, 0.8)
            assert net.output("A.DISTANCE")[0] == pytest.approx(d, abs=1e-6)
            assert net.output("A.CONTACT")[0] == (1 if d < 0.5 else 0)
            previous = expected
    finally:
        net.close()


# glibc's rand() after srand(1) (as unseeded) and srand(4), printed by the C library
GLIBC_1 = [1804289383, 846930886, 1681692777, 1714636915, 1957747793, 424238335]
GLIBC_4 = [1968078301, 287724083, 410622274, 558519326]


def test_random_targets_are_the_c_librarys_every_100_ticks(tmp_path):
    runs = []
    for seed in ("", 'seed="4"'):
        net = load(tmp_path, f'<module class="PlanarArm" name="A" {seed}/>')
        targets = []
        for _ in range(250):
            net.step()
            targets.append(net.output("A.TARGET").copy())
        net.close()
        runs.append(np.array(targets))
    for t, draws in zip(runs, (GLIBC_1, GLIBC_4)):
        changes = [i for i in range(1, len(t)) if not np.array_equal(t[i], t[i - 1])]
        assert changes == [100, 200]                         # ticks 100 and 200
        expected = 0.1 + 0.8 * np.array(draws[:4]) / 2147483647
        assert np.allclose(t[0], expected[:2]) and np.allclose(t[100], expected[2:4])
    assert np.allclose(runs[0][0], [0.772150159, 0.415506303])    # golden-v2 PlanarArm


def test_grasp_gives_a_new_target(tmp_path):
    net = arm(tmp_path, angles="0 0 0", grasp_limit=2, seed=1)
    try:
        targets = []
        for _ in range(5):
            net.step()
            targets.append(net.output("A.TARGET").copy())
        expected = 0.1 + 0.8 * np.array(GLIBC_1) / 2147483647
        assert np.allclose(targets[:3], expected.reshape(3, 2))
    finally:
        net.close()


def test_target_noise_does_not_accumulate(tmp_path):
    net = load(tmp_path, '<module class="PlanarArm" name="A" seed="7" target_noise="0.01"/>')
    try:
        targets = []
        for _ in range(99):                  # one random target for ticks 0 .. 98
            net.step()
            targets.append(net.output("A.TARGET").copy())
        targets = np.array(targets)
        steps = np.diff(targets, axis=0)
        # independent noise around a fixed point: the std of the differences is sqrt(2)
        # times the noise, and the spread does not grow (a random walk would reach ~0.1)
        assert 0.007 < steps.std() / math.sqrt(2) < 0.013
        assert np.abs(targets - targets.mean(axis=0)).max() < 0.05
    finally:
        net.close()


# --- the Ikaros 3 interface: JOINT_COMMAND and GRIPPER -----------------------------------------

def test_v3_joint_command_moves_the_arm_as_desired_angles(tmp_path):
    (tmp_path / "v3").mkdir()
    v2 = arm(tmp_path, "0.2 0.5 1", speed=0.3, seed=1)
    v3 = load(tmp_path / "v3", '<module class="Constant" name="D" data="0.2 0.5 1"/>'
                               '<module class="PlanarArm" name="A" speed="0.3" seed="1"/>'
                               '<connection source="D.OUTPUT" target="A.JOINT_COMMAND" '
                               'delay="0"/>')
    try:
        for _ in range(3):
            v2.step()
            v3.step()
            assert np.array_equal(v2.output("A.ANGLES"), v3.output("A.ANGLES"))
        assert np.allclose(v3.output("A.ANGLES"), [0.2, 0.5, 1.0])
        assert np.allclose(v3.output("A.JOINTS"), joints(0.2, 0.5, 1.0), atol=1e-6)
    finally:
        v2.close()
        v3.close()


def test_v3_both_angle_inputs_is_an_error(tmp_path):
    import ikaros
    with pytest.raises(ikaros.ModelError, match="not both"):
        load(tmp_path, '<module class="Constant" name="D" data="0 0 0"/>'
                       '<module class="PlanarArm" name="A"/>'
                       '<connection source="D.OUTPUT" target="A.DESIRED_ANGLES"/>'
                       '<connection source="D.OUTPUT" target="A.JOINT_COMMAND"/>')


def test_v3_gripper_grasps_only_when_closed(tmp_path):
    """target_size 2 keeps the hand in contact, so the random target is redrawn exactly on
    the ticks the gripper is closed."""
    (tmp_path / "g.txt").write_text("G/1\n0\n0\n1\n0\n1\n")
    net = load(tmp_path, '<module class="InputFile" name="F" filename="g.txt"/>'
                         '<module class="PlanarArm" name="A" seed="5" target_size="2"/>'
                         '<connection source="F.G" target="A.GRIPPER" delay="0"/>',
               dialect=2)        # Ikaros 2's arm, with Ikaros 3's GRIPPER input
    try:
        targets = [net.output("A.TARGET").copy()]
        for _ in range(5):
            net.step()
            targets.append(net.output("A.TARGET").copy())
        changed = [not np.array_equal(a, b) for a, b in zip(targets, targets[1:])]
        assert changed == [True, False, True, False, True]     # tick 0 draws one anyway
    finally:
        net.close()
