"""The virtual Dynamixel bus, driven through the dynamixel-sdk bus and at the byte level."""
from __future__ import annotations

import subprocess
import sys
import time

import pytest
import serial

from ikaros.hardware import DeviceError
from ikaros.hardware.dynamixel import protocol as p
from ikaros.hardware.dynamixel.bus import DynamixelBus
from ikaros.hardware.dynamixel.simulator import VirtualDynamixelBus, parse_ids
from ikaros.testing import wait_for

H = bytes.fromhex
# How long the driver waits for an answer is 2 x the adapter latency + 2 ms. The simulator is a
# thread of this process: on a busy machine it may wait for a CPU that long, so the tests wait
# generously (a servo that is not there then costs about 0.2 s).
LATENCY_MS = 100.0


def open_bus(path: str, baud_rate: int = 1000000, protocol: int = 2) -> DynamixelBus:
    return DynamixelBus(path, baud_rate, protocol, LATENCY_MS)


@pytest.fixture(params=[1, 2])
def rig(request):
    protocol = request.param
    model = "AX-12A" if protocol == 1 else "XM430-W350"
    sim = VirtualDynamixelBus({i: model for i in (1, 2, 3)}, protocol).start()
    bus = open_bus(sim.path, 1000000, protocol)
    yield sim, bus
    bus.close()
    sim.stop()


def roles(sim, ident):
    return sim.servo(ident).table


def test_byte_level_answers():
    with VirtualDynamixelBus({1: "AX-12A"}, 1) as sim:
        port = serial.Serial(sim.path, 1000000, timeout=1.0)
        port.write(H("FF FF 01 02 01 FB"))
        assert port.read(6) == H("FF FF 01 02 00 FC")
        port.write(H("FF FF 01 04 02 2B 01 CC"))                # read the temperature
        assert port.read(7) == H("FF FF 01 03 00 1E DD")         # 30 degrees
        port.close()
    with VirtualDynamixelBus({1: "XM430-W350"}, 2) as sim:
        port = serial.Serial(sim.path, 1000000, timeout=1.0)
        port.write(H("FF FF FD 00 01 03 00 01 19 4E"))
        assert port.read(14) == p.packet2(1, p.STATUS, bytes([0, 0xFC, 0x03, 45]))
        port.close()


def test_scan_ping_and_model_numbers(rig):
    sim, bus = rig
    number = 12 if bus.protocol == 1 else 1020
    assert bus.scan(range(0, 6)) == {1: number, 2: number, 3: number}
    assert bus.ping(9) is None


def test_goal_position_is_followed_at_the_moving_speed(rig):
    sim, bus = rig
    table = roles(sim, 1)
    goal, speed, torque = (table.role(n) for n in ("GOAL_POSITION", "MOVING_SPEED", "TORQUE_ENABLE"))
    bus.write(1, speed.field.address, speed.to_raw(0.5).to_bytes(speed.field.size, "little"))
    bus.write(1, torque.field.address, b"\x01")
    packets = sim.packets
    started = time.perf_counter()
    bus.sync_write(goal.field.address, goal.field.size,
                   {1: goal.to_raw(200.0).to_bytes(goal.field.size, "little"),
                    2: goal.to_raw(100.0).to_bytes(goal.field.size, "little")})
    assert wait_for(lambda: sim.packets > packets)     # the servos have the goal (no answer comes)
    present = table.role("PRESENT_POSITION")
    # half of 114 rpm is 342 degrees/s: 20 degrees take about 58 ms
    time.sleep(0.02)
    midway = present.to_value(int.from_bytes(bus.read(1, present.field.address, present.field.size), "little"))
    elapsed = time.perf_counter() - started
    assert 180.0 < midway <= min(200.0, 180.0 + 342.1 * elapsed) + 0.3
    time.sleep(0.1)
    values = bus.sync_read(present.field.address, present.field.size, [1, 2])
    assert present.to_value(int.from_bytes(values[1], "little")) == pytest.approx(200.0, abs=0.3)
    # servo 2's torque was off: the goal switches it on in the Protocol 1.0 series (their
    # firmware does; Ikaros 2 relies on it), not in the X series (e-Manual, XM430-W350,
    # "Torque Enable(64)": only writing 1 there turns the torque on)
    if bus.protocol == 1:
        assert wait_for(lambda: abs(sim.servo(2).value("PRESENT_POSITION") - 100.0) < 0.3)
    else:
        assert present.to_value(int.from_bytes(values[2], "little")) == pytest.approx(180.0, abs=0.3)


def test_angle_limit_error_and_overload(rig):
    sim, bus = rig
    table = roles(sim, 1)
    low = table.role("MIN_POSITION")
    bus.write(1, low.field.address, low.to_raw(90.0).to_bytes(low.field.size, "little"))
    goal = table.role("GOAL_POSITION")
    error = bus.write(1, goal.field.address, goal.to_raw(60.0).to_bytes(goal.field.size, "little"))
    assert error == (p.P1_ANGLE_LIMIT if bus.protocol == 1 else p.P2_DATA_LIMIT)
    bus.write(1, table.role("TORQUE_ENABLE").field.address, b"\x01")
    sim.set_external_load(1, 1.2)
    loaded_for = 0.45
    time.sleep(loaded_for)
    error = bus.write(1, table.role("LED").field.address, b"\x01")
    if bus.protocol == 1:
        assert error & p.P1_OVERLOAD
    else:
        assert error & p.P2_ALERT
        assert bus.read(1, table.role("HARDWARE_ERROR").field.address, 1) == bytes([p.HW_OVERLOAD])
    assert bus.read(1, table.role("TORQUE_ENABLE").field.address, 1) == b"\x00"
    assert sim.servo(1).temperature > 30.0 + 0.5 * 4.0 * 1.2 ** 2 * loaded_for     # heating 4 C/s x load^2


def test_faults_name_the_servo_and_the_bus(rig):
    sim, bus = rig
    sim.silence(2)
    with pytest.raises(DeviceError, match=rf"servo 2 on {sim.path} \(Protocol {bus.protocol}.0, 1000000 baud\) does not answer"):
        bus.read(2, 0, 2)
    sim.silence(2, silent=False)
    sim.corrupt(1)                                   # one corrupt packet is asked for again
    assert len(bus.read(2, 0, 2)) == 2
    sim.corrupt(2)
    with pytest.raises(DeviceError, match="servo 2 .* answered with a corrupt packet"):
        bus.read(2, 0, 2)
    sim.answer_as(3, 7)
    with pytest.raises(DeviceError, match="servo 3 .* does not answer"):
        bus.read(3, 0, 2)
    sim.answer_as(3, None)
    sim.disconnect()
    with pytest.raises(DeviceError, match="was lost"):
        bus.read(1, 0, 2)


def test_bulk_read_and_write_and_changing_an_id():
    with VirtualDynamixelBus({1: "XM430-W350", 2: "XL430-W250"}, 2) as sim:
        bus = open_bus(sim.path, 1000000, 2)
        bus.bulk_write([(1, 65, b"\x01"), (2, 112, (100).to_bytes(4, "little"))])
        assert bus.bulk_read([(1, 65, 1), (2, 112, 4)]) == {1: b"\x01", 2: (100).to_bytes(4, "little")}
        bus.write(2, 7, b"\x05")
        assert bus.scan([2, 5]) == {5: 1060}
        bus.close()


def test_a_servo_at_another_baud_rate_does_not_answer():
    with VirtualDynamixelBus({1: "AX-12A"}, 1, baud_rate=57600) as sim:
        assert open_bus(sim.path, 1000000, 1).ping(1) is None
        assert open_bus(sim.path, 57600, 1).ping(1) == 12


def test_line_time_makes_packets_take_their_wire_time():
    with VirtualDynamixelBus({i: "XM430-W350" for i in range(1, 11)}, 2, baud_rate=57600, line_time=True) as sim:
        bus = open_bus(sim.path, 57600, 2)
        started = time.perf_counter()
        bus.sync_read(132, 4, range(1, 11))
        # 14 bytes out, 10 x 15 bytes back: 164 bytes of 10 bits at 57600 baud = 28.5 ms
        assert time.perf_counter() - started >= 164 * 10 / 57600
        bus.close()


def test_parse_ids():
    assert parse_ids("1-4,7") == [1, 2, 3, 4, 7]
    with pytest.raises(ValueError, match="1-x"):
        parse_ids("1-x")


def test_ikaros_sim_prints_the_device_path():
    process = subprocess.Popen([sys.executable, "-m", "ikaros.hardware.sim_cli", "dynamixel", "--ids", "1-19",
                                "--protocol", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        path = process.stdout.readline().strip()
        assert path.startswith("/dev/pts/")
        bus = open_bus(path, 1000000, 2)
        assert bus.scan(range(1, 20)) == {i: 1020 for i in range(1, 20)}
        bus.close()
    finally:
        process.terminate()
        assert process.wait(timeout=10) == 0


def test_protocol1_bulk_read_of_mx_servos_and_the_group_read():
    from ikaros.hardware.dynamixel.control_table import table_for_model
    from ikaros.hardware.dynamixel.servos import ServoGroup
    with VirtualDynamixelBus({1: "MX-28", 2: "MX-64"}, 1, positions={1: 90.0, 2: 270.0}) as sim:
        bus = open_bus(sim.path, 1000000, 1)
        assert bus.bulk_read([(1, 36, 2), (2, 0, 2)]) == {1: (1024).to_bytes(2, "little"),
                                                         2: (310).to_bytes(2, "little")}
        sent = sim.packets
        group = ServoGroup(bus, {1: table_for_model("MX-28"), 2: table_for_model("MX-64")})
        values = group.read(["PRESENT_POSITION", "PRESENT_TEMPERATURE"])
        assert values == {"PRESENT_POSITION": {1: 90.0, 2: 270.0}, "PRESENT_TEMPERATURE": {1: 30.0, 2: 30.0}}
        assert sim.packets == sent + 1                     # one bulk read packet for both
        bus.close()


def test_scan_finds_servos_at_any_baud_rate(capsys):
    from ikaros.hardware.dynamixel.scan import main
    with VirtualDynamixelBus({3: "XL430-W250", 4: "XL430-W250"}, 2, baud_rate=57600) as sim:
        assert main([sim.path, "--baud", "1000000", "57600", "--max-id", "5", "--protocol", "2",
                     "--latency", str(LATENCY_MS)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "id   3  XL430-W250      Protocol 2.0  57600 baud", "id   4  XL430-W250      Protocol 2.0  57600 baud"]


def test_byte_stuffing_end_to_end_through_the_sdk_and_the_simulator():
    with VirtualDynamixelBus({1: "XM430-W350"}, 2) as sim:
        bus = open_bus(sim.path, 1000000, 2)
        value = bytes.fromhex("FF FF FD 00")                 # Homing Offset: the header inside the data
        assert bus.write(1, 20, value) == 0
        assert bytes(sim.servo(1).memory[20:24]) == value
        assert bus.read(1, 18, 8) == bytes(sim.servo(1).memory[18:26])   # the status is stuffed too
        bus.close()


def test_faults_from_the_device_string():
    from ikaros.hardware.simulators import start_from_device_string
    sim = start_from_device_string("sim:dynamixel?ids=1-3&protocol=1&silent=2&load=3=0.5")
    try:
        bus = open_bus(sim.path, 1000000, 1)
        assert bus.scan([1, 2, 3]) == {1: 12, 3: 12}
        assert sim.servo(3).external_load == 0.5
        bus.close()
    finally:
        sim.stop()
    with pytest.raises(DeviceError, match="cannot start the Dynamixel simulator: .*servo ids 'x'"):
        start_from_device_string("sim:dynamixel?ids=x")


def test_a_torque_limit_of_0_gives_no_torque_and_a_limit_moves_the_servo(rig):
    """e-Manual, AX-12A "Torque Limit(34)" and XM430-W350 "Goal PWM(100)": the fraction of the
    maximum output used; at 0 the servo holds nothing and stays where it is."""
    sim, bus = rig
    table = roles(sim, 1)
    limit, goal, torque = (table.role(n) for n in ("TORQUE_LIMIT", "GOAL_POSITION", "TORQUE_ENABLE"))
    bus.write(1, limit.field.address, bytes(limit.field.size))
    bus.write(1, torque.field.address, b"\x01")
    bus.write(1, goal.field.address, goal.to_raw(200.0).to_bytes(goal.field.size, "little"))
    time.sleep(0.2)
    assert sim.servo(1).value("PRESENT_POSITION") == pytest.approx(180.0, abs=0.3)
    assert sim.servo(1).raw("PRESENT_LOAD") == 0
    bus.write(1, limit.field.address, limit.to_raw(0.5).to_bytes(limit.field.size, "little"))
    assert wait_for(lambda: abs(sim.servo(1).value("PRESENT_POSITION") - 200.0) < 0.3)


def test_a_temperature_set_is_read_on_the_bus_and_stays(rig):
    sim, bus = rig
    address = roles(sim, 2).role("PRESENT_TEMPERATURE").field.address
    sim.set_temperature(2, 64)
    time.sleep(0.2)                                         # it does not cool down by itself
    assert bus.read(2, address, 1) == bytes([64])
    assert bus.read(1, address, 1) == bytes([30])


def test_the_simulator_keeps_what_it_received(rig):
    sim, bus = rig
    goal = roles(sim, 1).role("GOAL_POSITION")
    bus.sync_write(goal.field.address, goal.field.size, {1: (600).to_bytes(goal.field.size, "little"),
                                                         2: (700).to_bytes(goal.field.size, "little")})
    bus.write(3, goal.field.address, (650).to_bytes(goal.field.size, "little"))
    assert wait_for(lambda: len(sim.writes()) == 3)
    size = goal.field.size
    assert sim.writes() == [(1, goal.field.address, (600).to_bytes(size, "little")),
                            (2, goal.field.address, (700).to_bytes(size, "little")),
                            (3, goal.field.address, (650).to_bytes(size, "little"))]
    assert sim.received_packets[-1][1].instruction == p.WRITE


def test_temperature_from_the_device_string():
    from ikaros.hardware.simulators import start_from_device_string
    sim = start_from_device_string("sim:dynamixel?ids=1-2&protocol=2&temperature=2=65")
    try:
        assert sim.servo(2).temperature == 65 and sim.servo(1).temperature == 30
    finally:
        sim.stop()
