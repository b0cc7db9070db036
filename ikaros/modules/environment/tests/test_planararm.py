"""Tests of the PlanarArm module: the forward kinematics match the formula, joint limits,
speed limits and the frame are respected, and the targets follow their paths."""
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


def test_forward_kinematics_match_the_formula(tmp_path):
    net = arm(tmp_path, speed=10, seed=1)
    try:
        j = net.output("A.JOINTS")
        assert j.shape == (4, 2)
        assert np.allclose(j, joints(0.4, 0.4, 0.4), atol=1e-6)             # start pose
        assert np.allclose(net.output("A.ANGLES"), [0.4, 0.4, 0.4])
        for a in [(0, 0, 0), (0.3, 0.5, 0.7), (-0.8, 1.2, 0.4), (-1.5, 2.0, 1.0),
                  (-1.0, 1.5, 0.5), (0.2, 0.0, 3.0)]:
            net.set_parameter("D.data", " ".join(map(str, a)))
            net.step()
            assert np.allclose(net.output("A.ANGLES"), a, atol=1e-6), a
            assert np.allclose(net.output("A.JOINTS"), joints(*a), atol=1e-6), a
            assert np.allclose(net.output("A.HAND_POSITION"), joints(*a)[3], atol=1e-6)
            d = np.hypot(*(joints(*a)[3] - net.output("A.TARGET")))
            assert net.output("A.DISTANCE")[0] == pytest.approx(d, abs=1e-6)
    finally:
        net.close()


def test_joint_limits_and_the_frame(tmp_path):
    net = arm(tmp_path, angles="0 0 0", speed=10)
    try:
        net.step()
        # elbow and wrist limits are 0..pi: -1 and 4 are clipped
        net.set_parameter("D.data", "0.2 -1 4")
        net.step()
        assert np.allclose(net.output("A.ANGLES"), [0.2, 0, math.pi], atol=1e-6)
        # a posture with the hand outside 0.01..0.99 is refused: the arm stays
        net.set_parameter("D.data", "-2 0 0")       # hand at x = 0.5 - 0.8 sin 2 < 0
        net.step()
        assert np.allclose(net.output("A.ANGLES"), [0.2, 0, math.pi], atol=1e-6)
        # the shoulder is limited to +-2 pi / 3
        net.set_parameter("D.data", "-2.5 2.5 0.5")
        net.step()
        a = net.output("A.ANGLES")
        assert a[0] == pytest.approx(-2 * math.pi / 3, abs=1e-6)
        assert np.allclose(net.output("A.JOINTS"), joints(*a), atol=1e-6)
    finally:
        net.close()


def test_speed_limits_the_largest_joint_change(tmp_path):
    # from 0.4 0.4 0.4 towards -0.6 0.4 0.9: the change (-1, 0, 0.5) is scaled to (-0.1, 0, 0.05)
    net = arm(tmp_path, angles="-0.6 0.4 0.9", speed=0.1)
    try:
        expected = np.array([0.4, 0.4, 0.4])
        for _ in range(12):
            net.step()
            change = np.array([-0.6, 0.4, 0.9]) - expected
            largest = np.abs(change).max()
            expected = expected + (change * 0.1 / largest if largest > 0.1 else change)
            assert np.allclose(net.output("A.ANGLES"), expected, atol=1e-5)
        assert np.allclose(expected, [-0.6, 0.4, 0.9])
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
    net = arm(tmp_path, angles="0 0 0", speed=10, target_behavior=kind, target_speed=0.3,
              target_range=0.2, target_size=0.5)
    try:
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
            d = math.hypot(0.5 - expected[0], 0.8 - expected[1])   # hand at (0.5, 0.8)
            assert net.output("A.DISTANCE")[0] == pytest.approx(d, abs=1e-6)
            assert net.output("A.CONTACT")[0] == (1 if d < 0.5 else 0)
    finally:
        net.close()


def test_random_target_every_100_ticks_and_the_seed(tmp_path):
    runs = []
    for seed in (4, 4, 5):
        net = load(tmp_path, f'<module class="PlanarArm" name="A" seed="{seed}"/>')
        targets = [net.output("A.TARGET")]
        for _ in range(250):
            net.step()
            targets.append(net.output("A.TARGET"))
        net.close()
        runs.append(np.array(targets))
    t = runs[0]
    assert np.array_equal(runs[0], runs[1]) and not np.array_equal(runs[0], runs[2])
    assert np.all((t >= 0.1) & (t <= 0.9))
    changes = [i for i in range(1, len(t)) if not np.array_equal(t[i], t[i - 1])]
    assert changes == [100, 200]          # entries 100 and 200 are ticks 99 and 199


def test_grasp_gives_a_new_target(tmp_path):
    net = arm(tmp_path, angles="0 0 0", speed=10, grasp_limit=2, seed=1)
    try:
        targets = []
        for _ in range(5):
            net.step()
            targets.append(net.output("A.TARGET"))
        assert all(not np.array_equal(a, b) for a, b in zip(targets, targets[1:]))
    finally:
        net.close()


def test_target_noise_does_not_accumulate(tmp_path):
    net = load(tmp_path, '<module class="PlanarArm" name="A" seed="7" target_noise="0.01"/>')
    try:
        targets = []
        for _ in range(99):                  # one random target for ticks 0 .. 98
            net.step()
            targets.append(net.output("A.TARGET"))
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
        assert changed == [False, False, True, False, True]
    finally:
        net.close()
