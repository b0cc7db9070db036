"""The Dynamixel module against the virtual Dynamixel bus: commands, feedback units, errors and
the safe state on every way a run ends."""
import math
import os
import re
import signal
import subprocess
import sys
import time

import pytest

from ikaros.errors import ModelError, RunError
from ikaros.hardware.dynamixel.simulator import VirtualDynamixelBus
from ikaros.testing import load_body, wait_for

XM = "XM430-W350"


def model(tmp_path, device, goals="200 0 90", params="", extra=""):
    """Goals in the order of the servos (index_mode indirect) unless ``params`` sets the mode;
    answers are waited for generously (the simulator may wait for a CPU on a busy machine).
    Unless ``params`` or ``extra`` say otherwise, the start-up delay and the torque ramp are
    left out (test_dynamixel_startup.py tests them) and TORQUE_LIMIT is 1 for every element."""
    if "index_mode" not in params:
        params += ' index_mode="indirect"'
    if "serial_latency" not in params:
        params += ' serial_latency="100"'
    if "start_up_delay" not in params:
        params += ' start_up_delay="0" torque_up_delay="0"'
    if "D.TORQUE_LIMIT" not in extra:
        extra += (f'<module class="Constant" name="Full" data="{" ".join("1" for _ in goals.split())}"/>\n'
                  '<connection source="Full.OUTPUT" target="D.TORQUE_LIMIT" delay="0"/>\n')
    body = (f'<module class="Constant" name="G" data="{goals}"/>\n'
            f'<module class="Dynamixel" name="D" device="{device}" print_info="none" {params}/>\n'
            '<connection source="G.OUTPUT" target="D.GOAL_POSITION" delay="0"/>\n' + extra)
    return load_body(tmp_path, body)


def ikaros2_file(path, device, goals, params=""):
    """A whole Ikaros 2 model file: goals and a torque limit of 1 from Constants; answers are
    waited for generously (the simulator runs in this test's process, another process's
    driver may wait for it on a busy machine)."""
    limit = " ".join("1" for _ in goals.split())
    params += ' serial_latency="100"'
    path.write_text(f'<group name="Arm" tick_duration="0.01">\n<module class="Constant" name="G" data="{goals}"/>\n'
                    f'<module class="Constant" name="L" data="{limit}"/>\n'
                    f'<module class="Dynamixel" name="D" device="{device}" {params}/>\n'
                    '<connection source="G.OUTPUT" target="D.GOAL_POSITION"/>\n'
                    '<connection source="L.OUTPUT" target="D.TORQUE_LIMIT"/>\n</group>\n')


@pytest.fixture
def bus():
    with VirtualDynamixelBus({1: XM, 2: XM, 4: "XL430-W250"}, 2) as sim:
        yield sim


def test_nothing_moves_at_start_up_and_goals_reach_the_servos(tmp_path, bus):
    net = model(tmp_path, bus.path, params='max_servo_id="5"')
    try:
        assert net.output("D.FEEDBACK_PRESENT_POSITION").tolist() == [180, 180, 180]
        assert not any(bus.servo(i).torque for i in (1, 2, 4))          # built: nothing written
        net.step()
        assert [bus.servo(i).torque for i in (1, 2, 4)] == [True, False, True]   # goal 0: no command
        assert bus.servo(1).value("GOAL_POSITION") == pytest.approx(200, abs=0.05)
        assert bus.servo(2).value("GOAL_POSITION") == 180.0                     # never written
        assert wait_for(lambda: abs(bus.servo(4).value("PRESENT_POSITION") - 90) < 0.1)
        net.step()
        assert net.output("D.FEEDBACK_PRESENT_POSITION") == pytest.approx([200, 180, 90], abs=0.1)
        assert net.output("D.FEEDBACK_GOAL_POSITION") == pytest.approx([200, 180, 90], abs=0.01)
        assert net.output("D.FEEDBACK_TORQUE_ENABLE").tolist() == [1, 0, 1]
        assert net.output("D.FEEDBACK_PRESENT_VOLTAGE").tolist() == pytest.approx([12.0] * 3)
        assert net.output("D.FEEDBACK_PRESENT_TEMPERATURE").tolist() == [30, 30, 30]
        assert net.output("D.ERRORS").shape == (3, 8)
    finally:
        net.close()
    assert not any(bus.servo(i).torque for i in (1, 2, 4))                # safe state: torque off


@pytest.mark.parametrize("unit, goal, factor", [("radians", math.pi / 2, math.pi / 180), ("tau", 0.75, 1 / 360)])
def test_angle_units(tmp_path, unit, goal, factor):
    with VirtualDynamixelBus({3: "AX-12A"}, 1) as sim:
        net = model(tmp_path, sim.path, goals=str(goal), params=f'angle_unit="{unit}" servo_id="3" protocol="1"')
        try:
            net.step()
            degrees = goal / factor
            assert sim.servo(3).value("GOAL_POSITION") == pytest.approx(degrees, abs=0.3)
            assert wait_for(lambda: abs(sim.servo(3).value("PRESENT_POSITION") - degrees) < 0.3)
            net.step()
            assert net.output("D.FEEDBACK_PRESENT_POSITION")[0] == pytest.approx(goal, abs=0.3 * factor)
        finally:
            net.close()


def test_direct_index_mode_speed_and_torque_enable(tmp_path, bus):
    """Ikaros 2's default: element i is the servo with id i, arrays of max id + 1 elements."""
    extra = ('<module class="Constant" name="T" data="0 0 1 0 0"/>\n'
             '<module class="Constant" name="S" data="0 0.25 0.25 0 0.5"/>\n'
             '<connection source="T.OUTPUT" target="D.TORQUE_ENABLE" delay="0"/>\n'
             '<connection source="S.OUTPUT" target="D.MOVING_SPEED" delay="0"/>')
    net = model(tmp_path, bus.path, goals="0 200 200 0 200",
                params='servo_id="1 2 4" index_mode="direct"',
                extra=extra)
    try:
        assert net.output("D.FEEDBACK_PRESENT_POSITION").shape == (5,)
        net.step()
        assert [bus.servo(i).torque for i in (1, 2, 4)] == [False, True, False]   # TORQUE_ENABLE rules
        assert bus.servo(2).raw("MOVING_SPEED") == round(0.25 / 0.0020087719)
        assert bus.servo(4).raw("MOVING_SPEED") == 0          # its TORQUE_ENABLE is 0: no speed, no goal
        net.step()
        assert net.output("D.FEEDBACK_MOVING_SPEED")[[1, 2, 4]] == pytest.approx([0, 0.25, 0])
        assert net.output("D.FEEDBACK_PRESENT_SPEED")[2] == pytest.approx(0.25, abs=0.01)   # moving
    finally:
        net.close()


def test_by_default_element_i_is_the_servo_with_id_i_as_in_ikaros_2(tmp_path):
    """An Ikaros 2 model for servos 1, 2, 3 (no index_mode): element 0 unused, reads 0."""
    with VirtualDynamixelBus({1: XM, 2: XM, 3: XM}, 2) as sim:
        body = (f'<module class="Constant" name="G" data="0 150 200 210"/>\n'
                '<module class="Constant" name="L" data="0 1 1 1"/>\n'
                f'<module class="Dynamixel" name="D" device="{sim.path}" print_info="none" servo_id="1 2 3" '
                'start_up_delay="0"/>\n'
                '<connection source="G.OUTPUT" target="D.GOAL_POSITION" delay="0"/>\n'
                '<connection source="L.OUTPUT" target="D.TORQUE_LIMIT" delay="0"/>\n')
        net = load_body(tmp_path, body)
        try:
            assert net.output("D.FEEDBACK_PRESENT_POSITION").tolist() == [0, 180, 180, 180]
            assert net.output("D.ERRORS").shape == (4, 8)
            net.step()
            assert [sim.servo(i).value("GOAL_POSITION") for i in (1, 2, 3)] == pytest.approx([150, 200, 210],
                                                                                             abs=0.1)
            assert net.output("D.FEEDBACK_GOAL_POSITION") == pytest.approx([0, 150, 200, 210], abs=0.1)
        finally:
            net.close()


def test_indirect_follows_the_listed_order_and_size_forces_the_array_size(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="150 200 210 0 0 0", params='servo_id="4 1 2" index_mode="indirect" size="6"')
    try:
        assert net.output("D.FEEDBACK_PRESENT_POSITION").tolist() == [180, 180, 180, 0, 0, 0]
        net.step()
        assert [bus.servo(i).value("GOAL_POSITION") for i in (4, 1, 2)] == pytest.approx([150, 200, 210], abs=0.1)
    finally:
        net.close()
    with pytest.raises(ModelError, match=r'size="3" leaves no element for servo 4 \(index_mode="direct" needs at '
                                         r'least 5\)'):
        model(tmp_path, bus.path, params='servo_id="1 2 4" index_mode="direct" size="3"')


def test_an_input_that_has_no_value_from_its_source_yet_is_not_written(tmp_path):
    """LED and TORQUE_LIMIT through a Scale (delays 1) arrive on tick 2: the zeros before are
    no LED value (nothing is written) and no torque limit (it stays at the 0 of the start)."""
    with VirtualDynamixelBus({1: "AX-12A"}, 1) as sim:
        sim.servo(1).memory[25] = 1                                         # LED on
        extra = ('<module class="Constant" name="L" data="0.5"/>\n<module class="Scale" name="S" factor="1"/>\n'
                 '<module class="Constant" name="Off" data="0"/>\n<module class="Scale" name="S2" factor="1"/>\n'
                 '<connection source="L.OUTPUT" target="S.INPUT"/>\n'
                 '<connection source="S.OUTPUT" target="D.TORQUE_LIMIT"/>\n'
                 '<connection source="Off.OUTPUT" target="S2.INPUT"/>\n'
                 '<connection source="S2.OUTPUT" target="D.LED"/>')
        net = model(tmp_path, sim.path, goals="200", params='protocol="1" servo_id="1"', extra=extra)
        try:
            net.step()
            net.step()
            assert sim.servo(1).raw("TORQUE_LIMIT") == 0                       # as written at the start
            assert sim.servo(1).raw("LED") == 1                                # not written
            net.step()
            assert sim.servo(1).raw("TORQUE_LIMIT") == 512
            assert sim.servo(1).raw("LED") == 0
        finally:
            net.close()


def test_goals_are_clipped_to_the_angle_limits_and_overload_is_reported(tmp_path):
    with VirtualDynamixelBus({1: "AX-12A"}, 1) as sim:
        sim.servo(1).memory[6:8] = (512 - 100).to_bytes(2, "little")      # CW limit 150.7 degrees
        net = model(tmp_path, sim.path, goals="100", params='protocol="1" servo_id="1"')
        try:
            net.step()
            assert sim.servo(1).raw("GOAL_POSITION") == 412
            sim.set_external_load(1, 1.5)
            time.sleep(0.4)
            net.step()
            net.step()
            assert net.output("D.ERRORS")[0].tolist() == [0, 0, 0, 0, 0, 1, 0, 0]       # overload (bit 5)
            assert any("servo 1 on" in m and "overload" in m for _, _, _, m in net.log)
            assert net.output("D.FEEDBACK_PRESENT_LOAD")[0] == 0                         # torque is off
        finally:
            net.close()


def test_a_lost_status_packet_is_asked_for_again_and_a_missed_one_is_counted(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="200 190 90", params='servo_id="1 2 4" feedback="position" serial_latency="100"')
    try:
        net.step()
        bus.lose(1)                     # servo 1's reply to the sync read: read again on its own
        net.step()
        assert net.output("D.MISSED_REPLIES").tolist() == [0, 0, 0]
        bus.lose(5)                     # the sync read's three and both of servo 1's own: missed this tick
        net.step()
        assert net.output("D.MISSED_REPLIES").tolist() == [1, 0, 0]
        net.step()
        assert net.output("D.MISSED_REPLIES").tolist() == [1, 0, 0]
        assert bus.packets > 0 and not any("does not answer" in m for _, _, _, m in net.log)
    finally:
        net.close()


def test_a_servo_silent_for_silent_ticks_stops_the_run_and_the_rest_is_made_safe(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="200 190 90", params='servo_id="1 2 4" silent_ticks="3" serial_latency="100"')
    net.step()
    bus.silence(2)
    net.step()
    net.step()
    assert net.output("D.MISSED_REPLIES").tolist() == [0, 2, 0]
    with pytest.raises(RunError, match=rf"servo 2 on {bus.path} \(Protocol 2.0, 1000000 baud\) does not answer "
                                       r"\(reading Present Current to Present Temperature, addresses 126..146\) "
                                       r"for 3 ticks in a row"):
        net.step()
    assert net.stopped
    assert [bus.servo(i).torque for i in (1, 2, 4)] == [False, True, False]
    named = {int(n) for _, _, _, m in net.log for n in re.findall(r"servo (\d+)", m)}
    assert named == {2}                                       # one servo, named consistently


def test_a_register_is_named_by_name_and_address(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="200", params='servo_id="1" feedback="position" max_temperature="0" silent_ticks="1" serial_latency="100"')
    bus.silence(1)
    with pytest.raises(RunError, match=r"servo 1 on .* does not answer \(reading Present Position, address 132\)"):
        net.step()


def test_a_lost_bus_stops_the_run(tmp_path, bus):
    net = model(tmp_path, bus.path, params='servo_id="1 2 4"')
    net.step()
    bus.disconnect()
    with pytest.raises(RunError, match="was lost"):
        net.step()


def test_another_modules_exception_makes_the_servos_safe(tmp_path, bus):
    (tmp_path / "Boom.py").write_text(
        "from ikaros.module import Module\n"
        "class Boom(Module):\n"
        "    '''Fails on its third tick.'''\n"
        "    def tick(self):\n"
        "        if self.clock.tick == 2:\n"
        "            raise ValueError('boom')\n")
    net = model(tmp_path, bus.path, params='servo_id="1 2"', extra='<module class="Boom" name="B"/>')
    with pytest.raises(RunError, match="boom"):
        net.run(ticks=10)
    assert net.tick == 3
    assert not bus.servo(1).torque


def test_hold_keeps_torque_and_stops_where_the_servo_is(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="300", params='servo_id="1" safe_state="hold"')
    net.step()
    assert wait_for(lambda: bus.servo(1).value("PRESENT_POSITION") > 190)       # on its way to 300
    net.close()
    servo = bus.servo(1)
    assert servo.torque
    assert 190 < servo.value("GOAL_POSITION") <= 300.1
    assert servo.value("GOAL_POSITION") == pytest.approx(servo.value("PRESENT_POSITION"), abs=1.0)


def test_the_watchdog_makes_the_servos_safe_when_ticks_stop_and_the_run_can_go_on(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="200", params='servo_id="1" watchdog="0.2"')
    try:
        net.step()
        assert bus.servo(1).torque
        assert wait_for(lambda: not bus.servo(1).torque, 2.0)
        net.step()                                    # the model still says so: on again
        assert bus.servo(1).torque
    finally:
        net.close()


def test_bad_setups_fail_at_load_with_the_device_named(tmp_path, bus):
    with pytest.raises(ModelError, match="servo 7 on .* does not answer"):
        model(tmp_path, bus.path, params='servo_id="1 7" strict_servo_id="yes"')
    with pytest.raises(ModelError, match="cannot open the Dynamixel bus at '/dev/ttyNOSUCH'"):
        model(tmp_path, "/dev/ttyNOSUCH")
    with VirtualDynamixelBus({1: "AX-12A", 2: "AX-12A"}, 1) as other:
        with pytest.raises(ModelError, match="no Dynamixel servo answers .* at 57600 baud"):
            model(tmp_path, other.path, params='baud_rate="57600" max_servo_id="3"')


def test_a_simulator_started_by_the_device_attribute(tmp_path):
    net = model(tmp_path, "sim:dynamixel?ids=1-2&amp;protocol=1", goals="150 210", params='max_servo_id="4"')
    try:
        net.step()
        time.sleep(0.2)
        net.step()
        assert net.output("D.FEEDBACK_PRESENT_POSITION") == pytest.approx([150, 210], abs=0.3)
    finally:
        net.close()


@pytest.mark.parametrize("how", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_of_an_ikaros_process_makes_the_servos_safe(tmp_path, bus, how):
    path = tmp_path / "arm.ikg"
    ikaros2_file(path, bus.path, "250 100", 'servo_id="1 2" index_mode="indirect"')
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in [os.getcwd(), os.environ.get("PYTHONPATH")] if p))
    process = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-r", str(path)], env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert wait_for(lambda: bus.servo(1).torque and bus.servo(2).torque, 20.0)
        process.send_signal(how)
        process.wait(timeout=10)
    finally:
        if process.poll() is None:
            process.kill()
    assert not bus.servo(1).torque and not bus.servo(2).torque


def test_a_script_that_never_closes_its_network_leaves_the_servos_safe(tmp_path, bus):
    path = tmp_path / "arm.ikg"
    ikaros2_file(path, bus.path, "250", 'servo_id="1" index_mode="indirect" start_up_delay="0"')
    script = f"import ikaros\nnet = ikaros.load({str(path)!r})\nnet.run(ticks=3)\nprint(net.output('D.FEEDBACK_TORQUE_ENABLE')[0])\n"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in [os.getcwd(), os.environ.get("PYTHONPATH")] if p))
    result = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert "D: 1 servos on" in result.stdout and result.stdout.split()[-1] == "1.0"   # torque was on
    assert not bus.servo(1).torque                                                     # and is off at exit


def test_two_networks_share_one_bus(tmp_path, bus):
    """Two modules on one bus, or a model rebuilt (by the web UI) while the old one runs."""
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    first = model(tmp_path / "a", bus.path, goals="200", params='servo_id="1"')
    second = model(tmp_path / "b", bus.path, goals="150", params='servo_id="2"')
    try:
        first.step()
        second.step()
        assert bus.servo(1).torque and bus.servo(2).torque
        first.close()
        assert not bus.servo(1).torque and bus.servo(2).torque
        assert wait_for(lambda: abs(bus.servo(2).value("PRESENT_POSITION") - 150) < 0.1)
        second.step()                                   # the bus stayed open for the second
        assert second.output("D.FEEDBACK_PRESENT_POSITION")[0] == pytest.approx(150, abs=0.1)
    finally:
        first.close()
        second.close()
    assert not bus.servo(2).torque


def test_the_end_of_a_batch_run_leaves_the_servos_safe(tmp_path, bus):
    path = tmp_path / "arm.ikg"
    ikaros2_file(path, bus.path, "250", 'servo_id="1" print_info="none" index_mode="indirect"')
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in [os.getcwd(), os.environ.get("PYTHONPATH")] if p))
    result = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-s", "20", str(path)], env=env,
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    servo = bus.servo(1)
    assert servo.value("GOAL_POSITION") == pytest.approx(250, abs=0.1) and not servo.torque


@pytest.mark.filterwarnings("ignore:.*httpx.*")
def test_the_web_ui_stop_button_leaves_the_servos_safe(tmp_path, bus):
    from starlette.testclient import TestClient

    from ikaros.webui.server import create_app
    net = model(tmp_path, bus.path, goals="200", params='servo_id="1" watchdog="60"')
    app = create_app(net)
    try:
        with TestClient(app) as client:
            assert client.post("/api/control", json={"state": "play"}).status_code == 200
            assert wait_for(lambda: bus.servo(1).torque, 5.0)
            client.post("/api/control", json={"state": "pause"})
            time.sleep(0.1)
            assert bus.servo(1).torque                          # paused: held until the watchdog
            assert client.post("/api/control", json={"state": "stop"}).status_code == 200
            assert not bus.servo(1).torque                      # stopped: safe at once
            client.post("/api/control", json={"state": "play"})     # the model runs again
            assert wait_for(lambda: bus.servo(1).torque, 5.0)
            client.post("/api/control", json={"state": "stop"})
            assert not bus.servo(1).torque
    finally:
        for each in {net, app.state.ui.net}:
            each.controller.stop()
            each.controller.join(5)
            each.close()


def test_the_safe_state_command_holds_until_resume(tmp_path, bus):
    net = model(tmp_path, bus.path, goals="200", params='servo_id="1"')
    try:
        net.step()
        assert bus.servo(1).torque
        net.command("D", "safe_state")
        assert not bus.servo(1).torque
        net.step()
        net.step()
        assert not bus.servo(1).torque                    # the goal does not take it back
        net.command("D", "resume")
        net.step()
        assert bus.servo(1).torque
        with pytest.raises(ValueError, match="unknown command 'jump'"):
            net.command("D", "jump")
    finally:
        net.close()


def test_a_missing_sdk_fails_at_load_with_the_pip_install(tmp_path, bus, monkeypatch):
    monkeypatch.setitem(sys.modules, "dynamixel_sdk", None)          # as if not installed
    with pytest.raises(ModelError, match=r"dynamixel_sdk.*pip install 'ikaros\[robots\]'"):
        model(tmp_path, bus.path)


def test_a_model_rebuilt_while_the_old_one_runs_takes_the_servos_over(tmp_path, bus):
    (tmp_path / "old").mkdir()
    (tmp_path / "new").mkdir()
    old = model(tmp_path / "old", bus.path, goals="200", params='servo_id="1"')
    old.step()
    new = model(tmp_path / "new", bus.path, goals="160", params='servo_id="1"')   # built while old runs
    old.close()                                          # the web UI then closes the old model
    assert not bus.servo(1).torque
    try:
        new.step()
        assert bus.servo(1).torque and bus.servo(1).value("GOAL_POSITION") == pytest.approx(160, abs=0.1)
    finally:
        new.close()



def test_a_failed_build_leaves_the_port_closed(tmp_path, bus):
    (tmp_path / "FailingConfigure.py").write_text(
        "from ikaros.module import Module\n"
        "class FailingConfigure(Module):\n"
        "    \"\"\"Fails while the model is built (before any init).\"\"\"\n"
        "    def configure(self):\n"
        "        raise OSError('camera not found')\n")
    with pytest.raises(ModelError, match="camera not found"):
        model(tmp_path, bus.path, params='servo_id="1"', extra='<module class="FailingConfigure" name="F"/>')
    # were the port still open at 1 Mbaud, opening it at another rate would be refused
    with pytest.raises(ModelError, match="no Dynamixel servo answers"):
        model(tmp_path, bus.path, params='servo_id="1" baud_rate="57600"')
    assert not bus.servo(1).torque
