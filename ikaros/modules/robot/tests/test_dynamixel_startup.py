"""The Dynamixel module as Ikaros 2 drives the servos, on Protocol 1.0 and 2.0, seen on the bus:
start-up (torque limit 0, goal = present position, no instruction for ``start_up_delay``
ticks, the torque limit ramped over ``torque_up_delay`` ticks to TORQUE_LIMIT), the write
order within a tick, no goal or speed to a servo whose TORQUE_ENABLE is 0, heat, and the
parameters Ikaros 2 files use.

Expected raw values come from the ROBOTIS e-Manual's control tables: Protocol 1.0 (MX-64,
"Torque Limit(34)": 0..1023, about 0.1 % a unit; "Goal Position(30)": 0.088° a unit, 2048 the
centre) and Protocol 2.0 (XM430-W350, "Goal PWM(100)": 0..885 = 100 %, "Goal Position(116)":
0.088° a unit, 2048 the centre). Which field is written is read from the packets the
simulator received (``VirtualDynamixelBus.writes``)."""
import re

import pytest

from ikaros.errors import ModelError, RunError
from ikaros.hardware.dynamixel.simulator import VirtualDynamixelBus
from ikaros.testing import load_body

# per protocol: the model on the bus, and the e-Manual's addresses and full scales
SERIES = {
    1: {"model": "MX-64", "torque_limit": 34, "full_torque": 1023, "goal": 30, "torque_enable": 24,
        "order": {24: "TORQUE_ENABLE", 25: "LED", 26: "D_GAIN", 27: "I_GAIN", 28: "P_GAIN",
                  30: "GOAL_POSITION", 32: "MOVING_SPEED", 34: "TORQUE_LIMIT", 71: "GOAL_TORQUE",
                  73: "GOAL_ACCELERATION"}},
    2: {"model": "XM430-W350", "torque_limit": 100, "full_torque": 885, "goal": 116, "torque_enable": 64,
        "order": {64: "TORQUE_ENABLE", 65: "LED", 80: "D_GAIN", 82: "I_GAIN", 84: "P_GAIN",
                  116: "GOAL_POSITION", 112: "MOVING_SPEED", 100: "TORQUE_LIMIT", 102: "GOAL_TORQUE",
                  108: "GOAL_ACCELERATION"}},
}
IKAROS2_ORDER = ["TORQUE_ENABLE", "LED", "D_GAIN", "I_GAIN", "P_GAIN", "GOAL_POSITION", "MOVING_SPEED",
                 "TORQUE_LIMIT", "GOAL_TORQUE", "GOAL_ACCELERATION"]


def raw_degrees(degrees: float) -> int:
    """A 4096-step position (MX and X series): 0.088° a unit, 2048 at 180°."""
    return round(degrees / (360 / 4096))


def value(data: bytes) -> int:
    return int.from_bytes(data, "little")


def constant(name: str, data: str, target: str) -> str:
    return (f'<module class="Constant" name="{name}" data="{data}"/>\n'
            f'<connection source="{name}.OUTPUT" target="D.{target}" delay="0"/>\n')


def driver(sim, params: str, extra: str, **overrides):
    body = (f'<module class="Dynamixel" name="D" device="{sim.path}" print_info="none" servo_id="1 2" '
            f'index_mode="indirect" serial_latency="100" {params}/>\n' + extra)
    return load_body(sim.folder, body, **overrides)


@pytest.fixture(params=[1, 2], ids=["protocol1", "protocol2"])
def sim(request, tmp_path):
    series = SERIES[request.param]
    with VirtualDynamixelBus({1: series["model"], 2: series["model"]}, request.param,
                             positions={1: 150.0, 2: 210.0}) as bus:
        bus.series, bus.folder = series, tmp_path
        yield bus


def test_the_start_up_of_an_ikaros_2_model_ramps_the_torque_limit_on_the_bus(sim):
    """start_up_delay 3, torque_up_delay 4, TORQUE_LIMIT 0.8: at the start torque limit 0 and
    goal = present position; ticks 0..2 nothing at all; from tick 3 the torque limit written is
    0.8 × (tick − 3) / 4, then 0.8."""
    s = sim.series
    net = driver(sim, 'start_up_delay="3" torque_up_delay="4"',
                 constant("G", "200 160", "GOAL_POSITION") + constant("L", "0.8 0.8", "TORQUE_LIMIT"))
    try:
        start = sim.writes()
        assert [w for w in start if w[1] == s["torque_limit"]] == [(1, s["torque_limit"], bytes(2)),
                                                                   (2, s["torque_limit"], bytes(2))]
        goals = [(i, value(d)) for i, a, d in start if a == s["goal"]]
        assert goals == [(1, raw_degrees(150.0)), (2, raw_degrees(210.0))]      # where they are
        first = [k for k, w in enumerate(start) if w[1] == s["torque_limit"]][0]
        assert all(w[1] != s["goal"] for w in start[:first])                 # the torque limit first
        packets = len(sim.received_packets)
        for _ in range(3):
            net.step()
        assert len(sim.received_packets) == packets                            # no instruction at all
        limits = {1: [], 2: []}
        for _ in range(7):
            before = len(sim.writes())
            net.step()
            for ident, address, data in sim.writes()[before:]:
                if address == s["torque_limit"]:
                    limits[ident].append(value(data))
        expected = [round(0.8 * k / 4 * s["full_torque"]) for k in (1, 2, 3, 4)]   # 0 on tick 3: no change
        assert limits == {1: expected, 2: expected}
        assert sim.servo(1).raw("TORQUE_LIMIT") == round(0.8 * s["full_torque"])
        assert net.output("D.FEEDBACK_TORQUE_LIMIT").tolist() == pytest.approx([0.8, 0.8], abs=1e-3)
    finally:
        net.close()


def test_the_inputs_are_written_in_ikaros_2_order_and_no_goal_or_speed_without_torque(sim):
    s = sim.series
    extra = (constant("T", "1 0", "TORQUE_ENABLE") + constant("LED", "1 1", "LED")
             + constant("DG", "2 2", "D_GAIN") + constant("IG", "3 3", "I_GAIN") + constant("PG", "40 40", "P_GAIN")
             + constant("G", "200 160", "GOAL_POSITION") + constant("S", "0.2 0.2", "MOVING_SPEED")
             + constant("L", "1 1", "TORQUE_LIMIT") + constant("GT", "0.1 0.1", "GOAL_TORQUE")
             + constant("GA", "5 5", "GOAL_ACCELERATION"))
    net = driver(sim, 'start_up_delay="0" torque_up_delay="0"', extra)
    try:
        before = len(sim.writes())
        net.step()
        tick = sim.writes()[before:]
        roles = [s["order"][address] for _, address, _ in tick]
        runs = [r for k, r in enumerate(roles) if k == 0 or roles[k - 1] != r]   # one sync write a role
        assert runs == IKAROS2_ORDER
        by_servo = {ident: {s["order"][a] for i, a, _ in tick if i == ident} for ident in (1, 2)}
        assert by_servo[1] == set(IKAROS2_ORDER)
        assert by_servo[2] == set(IKAROS2_ORDER) - {"GOAL_POSITION", "MOVING_SPEED"}   # torque 0
        assert sim.servo(1).torque and not sim.servo(2).torque
        assert sim.servo(2).value("GOAL_POSITION") == pytest.approx(210.0, abs=0.1)   # never sent
    finally:
        net.close()


def test_a_servo_whose_torque_enable_is_0_gets_no_goal_on_any_tick(sim):
    s = sim.series
    extra = (constant("T", "0 0", "TORQUE_ENABLE") + constant("G", "200 160", "GOAL_POSITION")
             + constant("L", "1 1", "TORQUE_LIMIT"))
    net = driver(sim, 'start_up_delay="0" torque_up_delay="0" optimize="no"', extra)
    try:
        before = len(sim.writes())
        for _ in range(3):
            net.step()
        assert not [w for w in sim.writes()[before:] if w[1] == s["goal"]]
        assert not sim.servo(1).torque and not sim.servo(2).torque
    finally:
        net.close()


def test_a_servo_above_max_temperature_stops_the_run_in_the_safe_state(sim):
    net = driver(sim, 'start_up_delay="0" torque_up_delay="0"',
                 constant("G", "200 160", "GOAL_POSITION") + constant("L", "1 1", "TORQUE_LIMIT"))
    try:
        net.step()
        assert sim.servo(1).torque and sim.servo(2).torque
        sim.set_temperature(2, 60)
        net.step()                                          # 60 °C is not above 60
        sim.set_temperature(2, 66)
        with pytest.raises(RunError, match=rf"servo 2 on {re.escape(sim.path)} .* is at 66 °C, above "
                                           r"max_temperature \(60 °C\): the servos are in the safe state "
                                           r"\(torque_off\)"):
            net.step()
        assert not sim.servo(1).torque and not sim.servo(2).torque
        printed = "\n".join(m for _, _, _, m in net.log)
        table = printed[printed.index("servo 2 is too hot"):]
        for ident, celsius in ((1, 30), (2, 66)):
            assert re.search(rf"\n\s+{ident}\s+{re.escape(sim.series['model'])}\s.*°\s.*\s{celsius} °C\s+1\s", table)
    finally:
        net.close()


def test_max_temperature_is_a_parameter(sim):
    net = driver(sim, 'start_up_delay="0" max_temperature="70"',
                 constant("G", "200 160", "GOAL_POSITION") + constant("L", "1 1", "TORQUE_LIMIT"))
    try:
        net.step()
        sim.set_temperature(1, 66)
        net.step()
        net.step()
        assert sim.servo(1).torque
        assert net.output("D.FEEDBACK_PRESENT_TEMPERATURE").tolist() == [66, 30]
    finally:
        net.close()


def test_optimize_sends_only_what_changed(sim):
    s = sim.series
    for optimize, goal_writes in (("yes", 1), ("no", 3)):
        net = driver(sim, f'start_up_delay="0" torque_up_delay="0" optimize="{optimize}"',
                     constant("G", "200 160", "GOAL_POSITION") + constant("L", "1 1", "TORQUE_LIMIT"))
        try:
            before = len(sim.writes())
            for _ in range(3):
                net.step()
            sent = [w for w in sim.writes()[before:] if w[1] == s["goal"] and w[0] == 1]
            assert len(sent) == goal_writes, optimize
        finally:
            net.close()


def test_torque_limit_is_required_in_an_ikaros_2_file_and_ramps_to_the_servos_own_in_an_ikaros_3_file(sim):
    s = sim.series
    with pytest.raises(ModelError, match="TORQUE_LIMIT is not connected: an Ikaros 2 file must connect it"):
        driver(sim, "", constant("G", "200 160", "GOAL_POSITION"))
    sim.servo(1).memory[s["torque_limit"]:s["torque_limit"] + 2] = (500).to_bytes(2, "little")
    net = driver(sim, 'start_up_delay="1" torque_up_delay="2"', constant("G", "200 160", "GOAL_POSITION"),
                 dialect="3")
    try:
        before = len(sim.writes())
        for _ in range(4):
            net.step()
        limits = [value(d) for i, a, d in sim.writes()[before:] if a == s["torque_limit"] and i == 1]
        assert limits == [250, 500]                     # the ramp ends at the limit it had
    finally:
        net.close()


def test_max_servo_id_is_12_in_an_ikaros_2_file_and_number_of_servos_takes_the_first(tmp_path):
    with VirtualDynamixelBus({3: "XM430-W350", 12: "XM430-W350", 13: "XM430-W350"}, 2) as bus:
        def scan(params, **overrides):
            body = (f'<module class="Dynamixel" name="D" device="{bus.path}" print_info="none" protocol="2" '
                    f'index_mode="indirect" {params}/>\n' + constant("L", "1 1 1", "TORQUE_LIMIT"))
            net = load_body(tmp_path, body, **overrides)
            size = net.output("D.FEEDBACK_PRESENT_POSITION").size
            net.close()
            return size
        assert scan("") == 2                                    # ids 0..12: servos 3 and 12
        assert scan("", dialect="3") == 3                       # ids 0..32
        assert scan('number_of_servos="1"') == 1
        with pytest.raises(ModelError, match=r"found 2 servos \(3, 12\); number_of_servos is 3"):
            scan('number_of_servos="3"')
