"""DynamixelConfigure against the simulated bus: scan, set a field on SET, ids, baud rates, reset."""
import pytest

from ikaros.errors import RunError
from ikaros.hardware.dynamixel.bus import DynamixelBus
from ikaros.hardware.dynamixel.simulator import VirtualDynamixelBus
from ikaros.testing import load_body


def configure(tmp_path, device, params, set_rows="0 1 1"):
    (tmp_path / "s.txt").write_text("S/1 A/1\n" + "\n".join(f"{s} 1" for s in set_rows.split()) + "\n")
    body = ('<module class="InputFile" name="In" filename="s.txt"/>\n'
            f'<module class="DynamixelConfigure" name="C" device="{device}" max_servo_id="6" {params}/>\n'
            '<connection source="In.S" target="C.SET" delay="0"/>\n'
            '<connection source="In.A" target="C.ACTIVE" delay="0"/>')
    return load_body(tmp_path, body)


def test_a_field_is_written_once_on_the_rising_edge_of_set(tmp_path):
    with VirtualDynamixelBus({1: "XM430-W350", 2: "XM430-W350"}, 2) as sim:
        sim.servo(1).memory[64] = 1                      # torque on: it is switched off first
        net = configure(tmp_path, sim.path, 'field="Return Delay Time" value="10"')
        assert any("servo 2: XM430-W350 (model number 1020)" in m for *_, m in net.log)
        net.step()
        assert sim.servo(1).raw("TORQUE_ENABLE") == 1 and sim.servo(1).memory[9] == 250
        net.step()
        assert [sim.servo(i).memory[9] for i in (1, 2)] == [10, 10]
        assert sim.servo(1).raw("TORQUE_ENABLE") == 0
        assert net.output("C.CHANGE_MODE")[0] == 1 and net.output("C.RESET_MODE")[0] == 0
        net.close()


def test_setting_an_id_and_a_baud_rate(tmp_path):
    with VirtualDynamixelBus({1: "AX-12A", 2: "AX-12A"}, 1) as sim:
        net = configure(tmp_path, sim.path, 'field="ID" value="5" servo_id="2"')
        net.run(ticks=2)
        net.close()
        assert sorted(s.ident for s in sim.servos.values()) == [1, 5]
        net = configure(tmp_path, sim.path, 'adress="4" value="34" servo_id="5"')   # 57600 baud
        net.run(ticks=2)
        net.close()
        assert sim.servo(5).baud_rate == 57600
        assert DynamixelBus(sim.path, 1000000, 1).ping(5) is None       # it no longer answers at 1 Mbaud
        assert DynamixelBus(sim.path, 57600, 1).ping(5) == 12
    with VirtualDynamixelBus({1: "AX-12A", 2: "AX-12A"}, 1) as sim:
        with pytest.raises(RunError, match="would give them all the same id"):
            configure(tmp_path, sim.path, 'field="ID" value="9"').run(ticks=2)


def test_factory_reset(tmp_path):
    with VirtualDynamixelBus({3: "XL430-W250"}, 2) as sim:
        sim.servo(3).memory[9] = 7
        net = configure(tmp_path, sim.path, 'reset_mode="yes"')
        net.run(ticks=2)
        net.close()
        assert sim.servo(3).memory[9] == 250 and sim.servo(3).ident == 3
        assert net.output("C.RESET_MODE")[0] == 1
