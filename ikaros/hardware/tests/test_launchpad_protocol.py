"""The Launchpad X messages against Novation's "Launchpad X Programmer's reference manual"
(System Exclusive header F0h 00h 20h 29h 02h 0Ch; Programmer/Live mode switch 0Eh <mode>;
LED lighting 03h with colour specs <type> <LED> <data>, RGB type 03h with red, green, blue
0..127; the Programmer layout: pads 11 (bottom left) to 88 (top right), scene-launch buttons
19 ... 89, top buttons 91 ... 98), and the simulated Launchpad that answers them."""
import pytest

from ikaros.hardware import DeviceError, launchpad, midi
from ikaros.hardware.launchpad_sim import SimulatedLaunchpad


def test_the_mode_switch_is_the_manuals_message():
    assert launchpad.mode_switch(True).hex(" ") == "f0 00 20 29 02 0c 0e 01 f7"
    assert launchpad.mode_switch(False).hex(" ") == "f0 00 20 29 02 0c 0e 00 f7"


def test_led_lighting_with_rgb_colour_specs():
    message = launchpad.led_lighting({11: (127, 0, 0), 88: (0, 64, 127)})
    assert message.hex(" ") == "f0 00 20 29 02 0c 03 03 0b 7f 00 00 03 58 00 40 7f f7"
    command, data = launchpad.parse_sysex(message)
    assert command == 0x03
    assert launchpad.parse_colour_specs(data) == [(3, 11, (127, 0, 0)), (3, 88, (0, 64, 127))]


def test_programmer_layout_numbers():
    assert launchpad.pad_number(7, 0) == 11           # bottom left
    assert launchpad.pad_number(0, 7) == 88           # top right
    assert launchpad.pad_number(0, 8) == 89           # the top scene-launch button
    assert launchpad.pad_number(-1, 0) == 91          # the first top button
    assert launchpad.pad_position(11) == (7, 0)
    assert launchpad.pad_position(45) == (4, 4)
    assert launchpad.pad_position(19) is None and launchpad.pad_position(91) is None


def test_parsing_refuses_other_messages_and_short_specs():
    assert launchpad.parse_sysex(bytes([0x90, 11, 127])) is None
    assert launchpad.parse_sysex(bytes([0xF0, 0, 0x20, 0x29, 2, 0x0D, 3, 0xF7])) is None
    with pytest.raises(ValueError, match="bad colour spec at byte 0"):
        launchpad.parse_colour_specs(bytes([3, 11, 127]))


def test_the_simulator_answers_mode_lighting_and_note_messages():
    device = SimulatedLaunchpad()
    device.received(launchpad.mode_switch(True))
    assert device.mode == "programmer"
    device.received(bytes([0xF0, 0, 0x20, 0x29, 2, 0x0C, 3,
                           3, 11, 127, 0, 0,       # RGB
                           0, 12, 5,               # palette colour 5
                           1, 13, 5, 9,            # flashing between 9 and 5
                           2, 14, 45, 0xF7]))      # pulsing 45
    device.received(bytes([0x90, 15, 21]))        # Note On channel 1: palette 21
    device.received(bytes([0xB0, 19, 3]))         # Control Change: a side button
    assert device.leds == {11: ("rgb", 127, 0, 0), 12: ("palette", 5),
                           13: ("flashing", 5, 9), 14: ("pulsing", 45), 15: ("palette", 21),
                           19: ("palette", 3)}
    assert device.colour(7, 0) == ("rgb", 127, 0, 0)
    device.received(bytes([0x80, 15, 0]))         # Note Off: dark
    device.received(launchpad.led_lighting({11: (0, 0, 0)}))
    assert 15 not in device.leds and 11 not in device.leds


def test_presses_are_notes_and_buttons_are_control_changes():
    device = SimulatedLaunchpad()
    queue = device.listen()
    device.press(7, 0, velocity=90)
    device.release(7, 0)
    device.press(0, 8)
    device.release(0, 8)
    assert [m.hex(" ") for m in queue] == ["90 0b 5a", "80 0b 00", "b0 59 7f", "b0 59 00"]


def test_sim_ports_share_one_device_until_the_last_is_closed():
    output = midi.open_port("sim:launchpad", output=True)
    reading = midi.open_port("sim:launchpad", output=False)
    try:
        assert output.name == "Simulated Launchpad X LPX MIDI In"
        assert reading.name == "Simulated Launchpad X LPX MIDI Out"
        assert "Simulated Launchpad X LPX MIDI In" in midi.port_names(output=True)
        device = output.device
        assert reading.device is device
        output.send(launchpad.mode_switch(True))
        assert device.mode == "programmer"
        device.press(3, 3)
        assert reading.pending() == [bytes([0x90, 54, 127])]           # row 5, column 4
        assert reading.pending() == []
    finally:
        output.close()
        reading.close()
    assert midi.running_devices() == []


def test_an_unknown_simulator_is_named():
    with pytest.raises(DeviceError, match="no simulated MIDI device called 'sim:nothing' "
                                          r"\(known: sim:launchpad\)"):
        midi.open_port("sim:nothing", output=False)
