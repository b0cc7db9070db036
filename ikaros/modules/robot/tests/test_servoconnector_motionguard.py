"""ServoConnector and MotionGuard against independent computations."""
import pytest

from ikaros.testing import load_body


def test_servo_connector_maps_inverts_and_offsets(tmp_path):
    net = load_body(tmp_path, '<module class="Constant" name="C" data="10 20 30"/>\n'
                    '<module class="ServoConnector" name="S" connector="3 1 0 2 9" pre_inverted="0 1 0 0"'
                    ' post_inverted="1 0 0 1" offset="5 180 7 -1" output_size="5"/>\n'
                    '<connection source="C.OUTPUT" target="S.INPUT"/>')
    net.step()
    assert net.output("S.OUTPUT").tolist() == [-(30 + 5), -10 + 180, 0, -(20 - 1), 0]
    net2 = load_body(tmp_path, '<module class="Constant" name="C" data="1 2"/>\n'
                     '<module class="ServoConnector" name="S" output_size="3"/>\n'
                     '<connection source="C.OUTPUT" target="S.INPUT"/>')
    net2.step()
    assert net2.output("S.OUTPUT").tolist() == [1, 2, 0]


def test_servo_connector_output_has_ten_elements_in_ikaros_2_and_inputs_size_in_ikaros_3(tmp_path):
    """MODULES (Ikaros 2): OUTPUT[@output_size], output_size=10; IKAROS3-INTERFACES: OUTPUT
    (size=INPUT.size), no output_size."""
    body = ('<module class="Constant" name="C" data="1 2 3"/>\n<module class="ServoConnector" name="S" connector="3 2 1"/>\n'
            '<connection source="C.OUTPUT" target="S.INPUT"/>')
    assert load_body(tmp_path, body).output("S.OUTPUT").size == 10
    net = load_body(tmp_path, body, dialect="3")
    net.step()
    net.step()
    assert net.output("S.OUTPUT").tolist() == [3, 2, 1]


def guard(tmp_path, inputs, references, params):
    """Runs MotionGuard on rows of INPUT and REFERENCE (delay 0) and returns OUTPUT and HOLD per tick."""
    (tmp_path / "in.txt").write_text("A/2\n" + "\n".join(" ".join(map(str, r)) for r in inputs) + "\n")
    (tmp_path / "ref.txt").write_text("A/2\n" + "\n".join(" ".join(map(str, r)) for r in references) + "\n")
    net = load_body(tmp_path, '<module class="InputFile" name="I" filename="in.txt"/>\n'
                    '<module class="InputFile" name="R" filename="ref.txt"/>\n'
                    f'<module class="MotionGuard" name="G" {params}/>\n'
                    '<connection source="I.A" target="G.INPUT" delay="0"/>\n'
                    '<connection source="R.A" target="G.REFERENCE" delay="0"/>')
    out = []
    for _ in inputs:
        net.step()
        out.append((net.output("G.OUTPUT").tolist(), float(net.output("G.HOLD")[0])))
    return out


def test_speed_and_range_limits_against_the_reference(tmp_path):
    rows = guard(tmp_path, [[200, 100], [200, 100], [400, 100]], [[180, 180], [190, 175], [195, 170]],
                 'max_speed="8" input_limit_min="0 150" input_limit_max="300"')
    assert [r[0] for r in rows] == [[188, 172], [198, 167], [203, 162]]
    assert [r[1] for r in rows] == [0, 0, 0]


def test_acceleration_limit_ramps_the_step_up_and_down(tmp_path):
    # the servo is stuck at 180: steps 1, 2, 3, 4 (acceleration 1); then target 184: braking would
    # want sqrt(2*1*4) = 2.83, but the step may fall by only 1 a tick: 3
    rows = guard(tmp_path, [[190, 180]] * 4 + [[184, 180]], [[180, 180]] * 5,
                 'max_speed="10" max_acceleration="1"')
    assert [r[0][0] for r in rows] == pytest.approx([181, 182, 183, 184, 183])
    assert [r[0][1] for r in rows] == [180] * 5


def test_missing_input_and_jumps_hold_until_the_input_is_steady(tmp_path):
    inputs = [[0, 0], [185, 185], [186, 186], [260, 186], [260, 186], [260, 186], [260, 186]]
    refs = [[180, 180], [181, 181], [183, 183], [184, 184], [185, 185], [186, 186], [186, 186]]
    rows = guard(tmp_path, inputs, refs, 'max_speed="2" max_jump="20" settle_ticks="2"')
    assert rows[0] == ([180, 180], 1.0)               # missing input: hold where the robot is
    assert rows[1] == ([180, 180], 1.0)               # steady 1 tick
    assert rows[2] == ([185, 185], 0.0)               # steady 2 ticks: 183 + max_speed
    assert rows[3] == ([184, 184], 1.0)               # jump: hold
    assert rows[4] == ([184, 184], 1.0)               # steady 1 tick
    assert rows[5] == ([188, 186], 0.0)               # steady 2 ticks: moves on at max_speed
    assert rows[6] == ([188, 186], 0.0)


def test_unknown_reference_gives_no_goal(tmp_path):
    rows = guard(tmp_path, [[200, 200]], [[0, 0]], 'max_speed="5"')
    assert rows[0] == ([0, 0], 0.0)
