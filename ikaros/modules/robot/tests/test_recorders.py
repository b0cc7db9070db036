"""MotionRecorder and SequenceRecorder: record, keyframes, play back with smoothing, save and load;
MotionRecorder recording an arm moved by hand on the simulated Dynamixel bus."""
import time

import numpy as np
import pytest

from ikaros.hardware.dynamixel.simulator import VirtualDynamixelBus
from ikaros.testing import load_body


def sequence(tmp_path, params=""):
    return load_body(tmp_path, f'<module class="SequenceRecorder" name="R" output_size="2" positions="1 2" '
                               f'tick_duration="0.1" {params}/>', tick_duration="0.1")


def test_keyframes_play_back_with_interpolation(tmp_path):
    net = sequence(tmp_path, 'mode_string="off" keypoint_time="0.4"')
    net.command("R", "keypoint")                           # (1, 2) at 0 ms
    net.command("R", "set", value=[5, -2])
    net.command("R", "keypoint")                           # (5, -2) at 400 ms
    assert net.output("R.LENGTHS")[0] == 2
    assert net.output("R.TIMESTAMPS")[:3].tolist() == [0, 400, 0]
    assert net.output("R.KEYPOINTS")[:2].tolist() == [[1, 2], [5, -2]]
    net.command("R", "play")
    rows = []
    for _ in range(6):
        net.step()
        rows.append(net.output("R.OUTPUT").tolist() + [net.output("R.TRIG_OUT")[0], net.output("R.STATE")[0]])
    # 100 ms ticks: linear from (1, 2) to (5, -2) over 400 ms, then held
    assert rows == [[1, 2, 0, 2], [2, 1, 0, 2], [3, 0, 0, 2], [4, -1, 0, 2], [5, -2, 1, 0], [5, -2, 0, 0]]


def test_smooth_interpolation_and_smoothing(tmp_path):
    net = sequence(tmp_path, 'mode_string="off" keypoint_time="0.4" interpolation="smooth" smoothing="0.5"')
    net.command("R", "keypoint")
    net.command("R", "set", value=[5, 2])
    net.command("R", "keypoint")
    net.command("R", "play")
    out = []
    for _ in range(3):
        net.step()
        out.append(net.output("R.OUTPUT")[0])
    ease = [1 + 4 * f * f * (3 - 2 * f) for f in (0, 0.25, 0.5)]
    expected, filtered = [], 5.0                           # the filter starts at the present values (5)
    for value in ease:
        filtered = 0.5 * filtered + 0.5 * value
        expected.append(filtered)
    assert out == pytest.approx(expected)


def test_record_save_load_and_trig(tmp_path):
    (tmp_path / "in.txt").write_text("X/2\n" + "\n".join(f"{t} {10 * t}" for t in range(6)) + "\n")
    body = ('<module class="InputFile" name="I" filename="in.txt"/>\n'
            '<module class="SequenceRecorder" name="R" output_size="2" mode_string="record" '
            'directory="m" filename="seq.%02d.txt" sample_interval="2"/>\n'
            '<connection source="I.X" target="R.INPUT" delay="0"/>')
    net = load_body(tmp_path, body, tick_duration="0.1")
    for _ in range(5):
        net.step()
    assert net.output("R.LENGTHS")[0] == 3                  # ticks 0, 2, 4
    net.command("R", "save")
    text = (tmp_path / "m" / "seq.00.txt").read_text().splitlines()
    assert text[0] == "# time_ms channel_0 channel_1"
    assert [list(map(float, line.split())) for line in text[1:]] == [[0, 0, 0], [200, 2, 20], [400, 4, 40]]
    net.close()
    (tmp_path / "t.txt").write_text("T/3\n0 0 0\n0 1 0\n0 1 0\n")
    (tmp_path / "m" / "seq.01.txt").write_text("0 7 8\n100 9 10\n")
    body2 = ('<module class="InputFile" name="T" filename="t.txt"/>\n'
             '<module class="SequenceRecorder" name="R" output_size="2" max_motions="3" directory="m" '
             'filename="seq.%02d.txt"/>\n<connection source="T.T" target="R.TRIG" delay="0"/>')
    net = load_body(tmp_path, body2, tick_duration="0.1")
    assert net.output("R.LENGTHS").tolist() == [3, 2, 0]    # loaded at start
    net.step()
    net.step()                                              # rising edge of element 1: play motion 1
    assert net.output("R.OUTPUT").tolist() == [7, 8]
    net.step()
    assert net.output("R.OUTPUT").tolist() == [9, 10]
    assert net.output("R.COMPLETED").tolist() == [0, 1, 0]


def test_a_recording_made_by_hand_is_played_back_on_the_servos(tmp_path):
    with VirtualDynamixelBus({1: "AX-12A", 2: "AX-12A"}, 1) as sim:
        body = (f'<module class="Dynamixel" name="Arm" device="{sim.path}" servo_id="1 2" index_mode="indirect" print_info="none" '
                'watchdog="0" start_up_delay="0" torque_up_delay="0"/>\n'
                '<module class="MotionRecorder" name="R" mode_string="off" directory="m"/>\n'
                '<module class="Constant" name="Full" data="1 1"/>\n'
                '<connection source="Arm.FEEDBACK_PRESENT_POSITION" target="R.INPUT"/>\n'
                '<connection source="R.OUTPUT" target="Arm.GOAL_POSITION"/>\n'
                '<connection source="R.TORQUE" target="Arm.TORQUE_ENABLE"/>\n'
                '<connection source="Full.OUTPUT" target="Arm.TORQUE_LIMIT"/>')
        net = load_body(tmp_path, body, tick_duration="0.02")
        try:
            # at the start the AX-12s hold with a torque limit of 0 (Ikaros 2's start-up; a goal
            # switches their torque on) until TORQUE 0 (off) comes round the loop
            for _ in range(5):
                net.step()
            assert not sim.servo(1).torque
            net.command("R", "record")
            path = [(180 + 5 * k, 180 - 3 * k) for k in range(10)]
            for a, b in path:
                sim.move_by_hand(1, a)
                sim.move_by_hand(2, b)
                net.step()
            net.step()
            net.command("R", "stop")
            net.step()
            net.step()
            assert sim.servo(1).torque                        # stop holds where the arm is
            recorded = net.output("R.KEYPOINTS")[:int(net.output("R.LENGTHS")[0])]
            assert recorded[1:11] == pytest.approx(np.array(path), abs=0.3)   # one tick of delay
            net.command("R", "save")
            net.command("R", "off")
            net.step()
            net.step()                                        # TORQUE reaches the arm one tick later
            assert not sim.servo(1).torque
            sim.move_by_hand(1, 150)
            sim.move_by_hand(2, 200)
            net.step()
            net.step()                                        # the moved position has gone round the loop
            net.command("R", "play")
            seen = []
            for _ in range(20):
                net.step()
                time.sleep(0.02)
                seen.append(sim.servo(1).value("PRESENT_POSITION"))
            assert seen[-1] == pytest.approx(225, abs=0.3)                 # the arm went the recorded way
            assert all(later >= earlier - 0.3 for earlier, later in zip(seen, seen[1:])), (seen, recorded)
            assert sim.servo(1).value("GOAL_POSITION") == pytest.approx(225, abs=0.3)
            assert sim.servo(2).value("GOAL_POSITION") == pytest.approx(153, abs=0.3)
            assert (tmp_path / "m" / "motion.00.dat").exists()
        finally:
            net.close()
        assert not sim.servo(1).torque
