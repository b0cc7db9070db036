"""MidiInput, LaunchpadLED and LaunchpadAnimation against the simulated Launchpad X, which
speaks the messages of Novation's "Launchpad X Programmer's reference manual" (presses as
Note On with the Programmer-layout number, LEDs lit by the LED lighting System Exclusive
message with RGB colour specs 0..127). No real MIDI device is opened."""
import colorsys
import math
import sys

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.hardware import launchpad, midi
from ikaros.modules.io import LaunchpadLED as led_module
from ikaros.testing import load_body as load, step_until


def device():
    return midi.running_devices()[0]


def test_midi_input_keys_gate_trig_and_counts(tmp_path):
    net = load(tmp_path, '<module class="MidiInput" name="M" source_name="sim:launchpad" '
                         'trig_hold_ticks="2"/>')
    try:
        lp = device()
        assert net.output("M.CONNECTED").tolist() == [1]
        assert net.output("M.SOURCE_COUNT").tolist() == [1]
        lp.press(7, 0)                                  # pad 11
        lp.press(0, 7)                                  # pad 88
        net.step()
        got = {n: net.output(f"M.{n}").tolist()[0] for n in
               ("KEY", "GATE", "TRIG", "EVENT_COUNT", "LAST_BATCH_COUNT")}
        assert got == {"KEY": 88, "GATE": 1, "TRIG": 1, "EVENT_COUNT": 2, "LAST_BATCH_COUNT": 2}
        lp.release(7, 0)
        net.step()
        assert net.output("M.GATE").tolist() == [1]     # 88 is still held
        assert net.output("M.TRIG").tolist() == [1]     # held for two ticks
        lp.release(0, 7)
        lp.press(1, 8)                                  # a scene button: Control Change 79
        lp.release(1, 8)
        net.step()
        assert net.output("M.KEY").tolist() == [79]
        assert net.output("M.GATE").tolist() == [0]
        assert net.output("M.EVENT_COUNT").tolist() == [3]
        assert net.output("M.LAST_BATCH_COUNT").tolist() == [3]
        net.step()
        net.step()
        assert net.output("M.TRIG").tolist() == [0]
        assert net.output("M.LAST_BATCH_COUNT").tolist() == [0]
    finally:
        net.close()
    assert midi.running_devices() == []


def test_launchpad_led_switches_modes_and_sends_changed_pads(tmp_path):
    second = " ".join(["1 0.5 0"] + ["0 0 1"] * 63) + " 0\n"
    (tmp_path / "c.txt").write_text("C/192 P/1\n" + " ".join(["1 0.5 0"] + ["0 0 0"] * 63)
                                    + " 1\n" + second + second)
    net = load(tmp_path, '<module class="InputFile" name="C" filename="c.txt"/>'
                         '<module class="LaunchpadLED" name="L" destination_name="sim:launchpad" '
                         'idle_brightness="0.5"/>'
                         '<connection source="C.C" target="L.COLOR" delay="0"/>'
                         '<connection source="C.P" target="L.PLAYING" delay="0"/>')
    try:
        lp = device()
        assert lp.mode == "programmer"
        assert lp.messages[0] == launchpad.mode_switch(True)
        net.step()                                      # playing: full brightness
        assert net.output("L.CONNECTED").tolist() == [1]
        assert net.output("L.LAST_UPDATE_COUNT").tolist() == [64]
        assert lp.colour(0, 0) == ("rgb", 127, 64, 0)   # rint(0.5 · 127) = 64
        net.step()                                      # idle: half
        assert net.output("L.LAST_UPDATE_COUNT").tolist() == [64]
        assert lp.colour(0, 0) == ("rgb", 64, 32, 0)
        assert lp.colour(7, 7) == ("rgb", 0, 0, 64)
        assert lp.messages[-1][:7] == bytes([0xF0, 0, 0x20, 0x29, 2, 0x0C, 3])
        net.step()                                      # the same colours: nothing sent
        assert net.output("L.LAST_UPDATE_COUNT").tolist() == [0]
    finally:
        net.close()
    assert lp.leds == {} and lp.mode == "live"          # cleared, back in Live mode
    assert lp.messages[-1] == launchpad.mode_switch(False)


def test_a_layout_of_nine_columns_lights_the_scene_buttons(tmp_path):
    colours = " ".join(["0 0 0"] * 8 + ["1 1 1"])
    net = load(tmp_path, f'<module class="Constant" name="C" data="{colours}"/>'
                         '<module class="LaunchpadLED" name="L" destination_name="sim:launchpad" '
                         'layout_width="9" clear_on_stop="no" restore_live_mode="no"/>'
                         '<connection source="C.OUTPUT" target="L.COLOR"/>')
    try:
        lp = device()
        net.step()
        assert lp.leds == {89: ("rgb", 127, 127, 127)}
    finally:
        net.close()
    assert lp.leds == {89: ("rgb", 127, 127, 127)} and lp.mode == "programmer"


def test_a_missing_launchpad_is_found_when_it_appears(tmp_path, monkeypatch):
    monkeypatch.setattr(midi, "require_ports", lambda name: None)
    monkeypatch.setattr(midi, "_backend", lambda: type("NoRealPorts", (), {
        "get_output_names": staticmethod(lambda: []),
        "get_input_names": staticmethod(lambda: [])})())
    monkeypatch.setattr(led_module, "RETRY_SECONDS", 0.0)
    net = load(tmp_path, '<module class="Constant" name="C" data="0 1 0"/>'
                         '<module class="LaunchpadLED" name="L" '
                         'destination_name="Simulated Launchpad X LPX MIDI In"/>'
                         '<connection source="C.OUTPUT" target="L.COLOR"/>')
    held = None
    try:
        assert net.output("L.CONNECTED").tolist() == [0]
        assert net.output("L.DESTINATION_COUNT").tolist() == [0]
        net.step()
        held = midi.open_port("sim:launchpad", output=False)     # the device is plugged in
        step_until(net, lambda: net.output("L.CONNECTED")[0] == 1, pause=0)
        assert net.output("L.DESTINATION_COUNT").tolist() == [1]
        assert held.device.mode == "programmer"
        assert held.device.colour(0, 0) == ("rgb", 0, 127, 0)
    finally:
        net.close()
        if held is not None:
            held.close()


def test_real_ports_need_python_rtmidi(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "rtmidi", None)
    with pytest.raises(ModelError, match=r"python-rtmidi: pip install 'ikaros\[midi\]'"):
        load(tmp_path, '<module class="MidiInput" name="M"/>')


def animation(tmp_path, attrs, rows=None, ticks=1, tick_duration="0.05"):
    body = f'<module class="LaunchpadAnimation" name="A" {attrs}/>'
    if rows is not None:
        (tmp_path / "k.txt").write_text("K/1 T/1 E/1\n" + "\n".join(rows) + "\n")
        body += ('<module class="InputFile" name="K" filename="k.txt"/>'
                 '<connection source="K.K" target="A.KEY" delay="0"/>'
                 '<connection source="K.T" target="A.TRIG" delay="0"/>'
                 '<connection source="K.E" target="A.EVENT_COUNT" delay="0"/>')
    net = load(tmp_path, body, tick_duration=tick_duration, dialect="2")   # time 0 first
    frames = []
    try:
        for _ in range(ticks):
            net.step()
            frames.append(net.output("A.COLOR").copy())
    finally:
        net.close()
    return frames


def rainbow(t, speed=1.0, brightness=1.0, saturation=0.9):
    rows = []
    for k in range(64):
        r, c = divmod(k, 8)
        hue = (0.1 * speed * t + (r + c) / 16) % 1.0
        w = 0.5 + 0.5 * math.sin(2 * math.pi * (0.25 * speed * t - r / 8))
        rows.append(colorsys.hsv_to_rgb(hue, saturation, brightness * (0.35 + 0.65 * w)))
    return np.array(rows)


def test_the_rainbow_and_the_wave_without_sparkles(tmp_path):
    frames = animation(tmp_path, 'sparkle="0" speed="2" brightness="0.8"', ticks=3)
    for k, frame in enumerate(frames):
        assert np.allclose(frame, rainbow(0.05 * k, 2.0, 0.8), atol=1e-6)


def test_frames_follow_the_frame_rate(tmp_path):
    frames = animation(tmp_path, 'sparkle="0" frame_rate="10"', ticks=4)
    assert np.array_equal(frames[0], frames[1])           # 0.05 s: no new frame yet
    assert np.allclose(frames[2], rainbow(0.1), atol=1e-6)
    assert np.array_equal(frames[2], frames[3])


def test_sparkles_are_white_and_the_same_every_run(tmp_path):
    first = animation(tmp_path, 'sparkle="4"', ticks=2)
    again = animation(tmp_path, 'sparkle="4"', ticks=2)
    assert np.array_equal(first[1], again[1])
    for number, frame in enumerate(first):
        k = np.arange(64)
        white = np.mod(43758.5453 * np.sin(12.9898 * k + 78.233 * number), 1) < 0.2
        assert white.any() and np.allclose(frame[white], 1.0)
        assert np.allclose(frame[~white], rainbow(0.05 * number)[~white], atol=1e-6)


def test_a_press_starts_a_ripple_at_its_pad(tmp_path):
    # pad 45: row 4 from the bottom, column 5: (4, 4) from the top left; pressed on tick 2
    frames = animation(tmp_path, 'sparkle="0" saturation="1" brightness="0.5"',
                       ["45 0 0", "45 1 1", "45 1 1"], ticks=3)
    assert np.allclose(frames[0], rainbow(0.0, 1.0, 0.5, 1.0), atol=1e-6)
    ring = np.array([math.exp(-math.hypot(r - 4, c - 4) ** 2) for r, c in
                     (divmod(k, 8) for k in range(64))])
    expected = []
    base = rainbow(0.05, 1.0, 0.5, 1.0)
    for k in range(64):
        h, s, v = colorsys.rgb_to_hsv(*base[k])
        expected.append(colorsys.hsv_to_rgb(h, 1 - min(1, ring[k]),
                                            min(1, v + 0.5 * ring[k])))
    assert np.allclose(frames[1], expected, atol=1e-6)
    pressed = frames[1][4 * 8 + 4]                               # the pressed pad is white
    assert pressed[0] == pressed[1] == pressed[2] > base[4 * 8 + 4].max()


def test_colours_stay_between_0_and_1(tmp_path):
    frames = animation(tmp_path, 'reactivity="5" sparkle="3" speed="7"',
                       ["11 1 1", "88 0 2", "0 1 3"], ticks=3)
    assert all(f.min() >= 0 and f.max() <= 1 for f in frames)
