"""EpiServos, DynamixelController and HeadServos: simulated in the model, and driven on the
virtual Dynamixel buses of an Epi described by a robot file beside the model.

Expected values: a simulated servo moves toward its goal by at most its no-load speed times
the tick duration (ROBOTIS e-Manual specifications: MX-106(2.0) 45 rpm, MX-28(2.0) 55 rpm,
XL-320 114 rpm; 1 rpm = 6°/s); positions are read on the bus in the e-Manual's units (X and
MX(2.0) "Goal Position(116)": 0.088° a unit); "Operating Mode(11)": 3 position control, 5
current-based position control; "Goal Current(102)": 3.36 mA a unit (MX-64/106(2.0))."""
import json

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.hardware.dynamixel.simulator import VirtualDynamixelBus
from ikaros.testing import load_body, wait_for

EPI = ["NeckTilt", "NeckPan", "LeftEye", "RightEye", "PupilLeft", "PupilRight"] + \
    [f"LeftArmJoint{j}" for j in range(1, 6)] + ["LeftHand"] + [f"RightArmJoint{j}" for j in range(1, 6)] + \
    ["RightHand", "Body"]
RPM = {"MX-106(2.0)": 45, "MX-28(2.0)": 55, "XL-320": 114}
ARM = ["MX-106(2.0)"] * 4 + ["MX-28(2.0)"] * 2
BUSES = {"head": {2: "MX-106(2.0)", 3: "MX-106(2.0)", 4: "MX-28(2.0)", 5: "MX-28(2.0)"},
         "pupil": {2: "XL-320", 3: "XL-320"},
         "left_arm": {2 + j: m for j, m in enumerate(ARM)}, "right_arm": {2 + j: m for j, m in enumerate(ARM)},
         "body": {2: "MX-106(2.0)"}}
MODELS = [BUSES["head"][i] for i in (2, 3, 4, 5)] + ["XL-320"] * 2 + ARM + ARM + ["MX-106(2.0)"]
LOW = [122, 130, 161, 156, -np.inf, -np.inf, 53, 73, 87, 53, 70, 0, 53, 79, 88, 158, 70, 0, 9]
HIGH = [237, 240, 202, 193, np.inf, np.inf, 281, 281, 263, 202, 342, 360, 281, 290, 264, 316, 343, 360, 343]
# answers are waited for generously: the simulator may wait for a CPU on a busy machine
LATENCY = 'serial_latency="100"'
GOALS = [200, 150, 170, 170, 200, 160, 100, 100, 100, 100, 100, 100, 250, 250, 250, 250, 250, 250, 400]


def simulated_steps(goals, ticks, dt, start=180.0, rate=None):
    """Positions tick by tick: toward the clipped goal by at most the no-load speed × dt
    (and, with ``rate``, at most that fraction of the distance)."""
    goal = np.clip(np.asarray(goals, float), LOW[:len(goals)], HIGH[:len(goals)])
    speed = np.array([RPM[m] * 6.0 for m in MODELS[:len(goals)]])
    present = np.full(len(goals), start)
    rows = []
    for _ in range(ticks):
        most = speed * dt if rate is None else np.minimum(speed * dt, rate * np.abs(goal - present))
        present = present + np.clip(goal - present, -most, most)
        rows.append(present.copy())
    return rows


def epi_model(tmp_path, cls, params, goals=GOALS, extra="", dt="0.05"):
    body = (f'<module class="Constant" name="G" data="{" ".join(map(str, goals))}"/>\n'
            f'<module class="{cls}" name="E" {params}/>\n'
            '<connection source="G.OUTPUT" target="E.GOAL_POSITION" delay="0"/>\n' + extra)
    return load_body(tmp_path, body, dialect="3", tick_duration=dt)


def test_simulated_epi_servos_move_at_their_top_speed_toward_the_clipped_goals(tmp_path):
    net = epi_model(tmp_path, "EpiServos", 'simulate="yes"')
    try:
        assert net.output("E.PRESENT_POSITION").tolist() == [180.0] * 19
        for expected in simulated_steps(GOALS, 14, 0.05):
            net.step()
            assert net.output("E.PRESENT_POSITION") == pytest.approx(expected, abs=1e-3)
        assert net.output("E.PRESENT_POSITION")[[0, 18]] == pytest.approx([200, 343], abs=1e-3)   # Body clipped
        assert net.output("E.PRESENT_CURRENT").tolist() == [0.0] * 19
    finally:
        net.close()


def test_simulated_dynamixel_controller_moves_a_fraction_of_the_way_a_tick(tmp_path):
    net = epi_model(tmp_path, "DynamixelController", 'robot="EpiGray" Simulate="yes" SimulationRate="0.4"',
                    goals=GOALS[:6])
    try:
        for k, expected in enumerate(simulated_steps(GOALS[:6], 5, 0.05, rate=0.4)):
            net.step()
            assert net.output("E.PRESENT_POSITION") == pytest.approx(expected, abs=1e-3)
        state = net.output("E.STATE")
        assert state[[0, 1, 2, 7, 8, 9]].tolist() == [1, 6, 6, 5, 2, 0]
        assert state[5] == pytest.approx(np.max(np.abs(np.clip(GOALS[:6], LOW[:6], HIGH[:6]) - expected)), abs=1e-3)
    finally:
        net.close()


@pytest.fixture
def epi(tmp_path):
    """The five buses of an Epi, simulated, and a robot file TestEpi beside the model."""
    buses = {name: VirtualDynamixelBus(servos, 2).start() for name, servos in BUSES.items()}
    (tmp_path / "robots").mkdir()
    (tmp_path / "robots" / "TestEpi.json").write_text(json.dumps(
        {"robot": "TestEpi", "type": "Epi", "ports": {name: bus.path for name, bus in buses.items()}}))
    yield buses
    for bus in buses.values():
        bus.stop()


def servo(buses, element):
    """The simulated servo of an element of the Epi's 19."""
    bus = ["head"] * 4 + ["pupil"] * 2 + ["left_arm"] * 6 + ["right_arm"] * 6 + ["body"]
    ident = [2, 3, 4, 5, 2, 3] + list(range(2, 8)) * 2 + [2]
    return buses[bus[element]].servo(ident[element])


def test_epi_servos_drive_the_epi_on_its_five_buses(tmp_path, epi):
    extra = ('<module class="Constant" name="T" data="1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 0"/>\n'
             '<connection source="T.OUTPUT" target="E.TORQUE_ENABLE" delay="0"/>\n')
    net = epi_model(tmp_path, "EpiServos", f'robot="TestEpi" {LATENCY}', extra=extra)
    try:
        assert net.output("E.PRESENT_POSITION").tolist() == pytest.approx([180.0] * 19, abs=0.1)
        assert not any(servo(epi, k).torque for k in range(19))            # nothing moved at the start
        net.step()
        goals = np.clip(GOALS, LOW, HIGH)
        for k in range(18):
            assert servo(epi, k).torque
            assert servo(epi, k).value("GOAL_POSITION") == pytest.approx(goals[k], abs=0.2)
        body = servo(epi, 18)                                               # TORQUE_ENABLE 0: no goal
        assert not body.torque and body.value("GOAL_POSITION") == pytest.approx(180, abs=0.1)
        assert wait_for(lambda: all(abs(servo(epi, k).value("PRESENT_POSITION") - goals[k]) < 0.3
                                    for k in range(18)))
        net.step()
        assert net.output("E.PRESENT_POSITION") == pytest.approx(list(goals[:18]) + [180], abs=0.3)
    finally:
        net.close()
    assert not any(servo(epi, k).torque for k in range(19))                # torque off at the end


def test_current_position_control_sets_the_operating_mode_and_writes_goal_currents(tmp_path, epi):
    extra = ('<module class="Constant" name="C" data="' + " ".join(["336"] * 19) + '"/>\n'
             '<connection source="C.OUTPUT" target="E.GOAL_CURRENT" delay="0"/>\n')
    net = epi_model(tmp_path, "EpiServos", f'robot="TestEpi" ServoControlMode="CurrentPosition" {LATENCY}', extra=extra)
    try:
        modes = [servo(epi, k).raw("OPERATING_MODE") if MODELS[k] != "XL-320" else None for k in range(19)]
        assert modes == [5 if m == "MX-106(2.0)" else 3 if m == "MX-28(2.0)" else None for m in MODELS]
        net.step()
        for k in range(19):
            if MODELS[k] == "MX-106(2.0)":
                assert servo(epi, k).raw("GOAL_CURRENT") == 100                 # 336 mA / 3.36 mA
    finally:
        net.close()


def test_a_servo_of_another_model_than_the_robot_type_says_is_an_error(tmp_path, epi):
    epi["body"].stop()
    other = VirtualDynamixelBus({2: "XM430-W350"}, 2).start()
    try:
        robot = json.loads((tmp_path / "robots" / "TestEpi.json").read_text())
        robot["ports"]["body"] = other.path
        (tmp_path / "robots" / "TestEpi.json").write_text(json.dumps(robot))
        with pytest.raises(ModelError, match=r"servo Body \(id 2 on the body bus, .*\) is a XM430-W350; the robot "
                                             r"type Epi says MX-106\(2.0\)"):
            epi_model(tmp_path, "EpiServos", f'robot="TestEpi" {LATENCY}').step()
    finally:
        other.stop()


def test_an_unknown_robot_names_the_known_ones(tmp_path):
    with pytest.raises(ModelError, match=r"no robot called 'EpiPurple' \(known: .*EpiWhite"):
        epi_model(tmp_path, "EpiServos", 'robot="EpiPurple" simulate="yes"')


def test_dynamixel_controller_drives_the_first_servo_count_servos_of_a_robot(tmp_path, epi):
    net = epi_model(tmp_path, "DynamixelController", f'robot="TestEpi" ServoCount="4" {LATENCY}', goals=GOALS[:4])
    try:
        assert net.output("E.PRESENT_POSITION").size == 4
        net.step()
        assert [servo(epi, k).value("GOAL_POSITION") for k in range(4)] == pytest.approx(GOALS[:4], abs=0.2)
        assert not servo(epi, 4).torque                                     # the pupils are not used
        state = net.output("E.STATE")
        assert state[[0, 1, 2, 3, 8]].tolist() == [0, 4, 4, 0, 1]
    finally:
        net.close()


def test_head_servos_on_their_port(tmp_path):
    with VirtualDynamixelBus({2: "MX-106(2.0)", 3: "MX-106(2.0)"}, 2) as bus:
        body = (f'<module class="Constant" name="G" data="200 150"/>\n<module class="Constant" name="T" data="1 0"/>\n'
                f'<module class="HeadServos" name="H" port="{bus.path}" {LATENCY}/>\n'
                '<connection source="G.OUTPUT" target="H.GOAL_POSITION" delay="0"/>\n'
                '<connection source="T.OUTPUT" target="H.TORQUE_ENABLE" delay="0"/>\n')
        net = load_body(tmp_path, body, dialect="3")
        try:
            net.step()
            assert bus.servo(2).torque and not bus.servo(3).torque
            assert bus.servo(2).value("GOAL_POSITION") == pytest.approx(200, abs=0.1)
            assert bus.servo(3).value("GOAL_POSITION") == pytest.approx(180, abs=0.1)
            assert wait_for(lambda: abs(bus.servo(2).value("PRESENT_POSITION") - 200) < 0.2)
            net.step()
            assert net.output("H.PRESENT_POSITION") == pytest.approx([200, 180], abs=0.2)
        finally:
            net.close()
        assert not bus.servo(2).torque
    with pytest.raises(ModelError, match="cannot open the Dynamixel bus at '/dev/cu.usbserial-A40129WB'"):
        load_body(tmp_path, body.replace(f'port="{bus.path}"', ""), dialect="3").step()
