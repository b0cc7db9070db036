"""The FadeCandy module against the simulated OPC server."""
import os
import socket
import subprocess
import sys
import time

import pytest

from ikaros.errors import ModelError, RunError
from ikaros.hardware.opc_sim import VirtualOPCServer
from ikaros.testing import load_body, wait_for

CHANNELS = '<channel name="EYES" channel="1" size="3"/><channel name="MOUTH" channel="2" size="2"/>'


def model(tmp_path, address, params='start_server="no"', channels=CHANNELS):
    body = ('<module class="Constant" name="R" data="1 0.5 0"/>\n'
            '<module class="Constant" name="B" data="0.2 2"/>\n'
            f'<module class="FadeCandy" name="LED" address="{address}" {params}>{channels}'
            '</module>\n'
            '<connection source="R.OUTPUT" target="LED.EYES_RED" delay="0"/>\n'
            '<connection source="B.OUTPUT" target="LED.MOUTH_BLUE" delay="0"/>')
    return load_body(tmp_path, body)


def test_channels_become_inputs_and_pixels_arrive(tmp_path):
    with VirtualOPCServer() as server:
        net = model(tmp_path, server.path)
        inputs, _ = net.ports("LED")
        assert [i.name for i in inputs] == ["LEFT_EYE", "RIGHT_EYE", "MOUTH_HIGH", "MOUTH_LOW",   # Ikaros 3's
                                            "EYES_RED", "EYES_GREEN", "EYES_BLUE",
                                            "MOUTH_RED", "MOUTH_GREEN", "MOUTH_BLUE"]
        time.sleep(0.05)
        assert server.messages == []                    # nothing before the first tick
        net.step()
        assert wait_for(lambda: len(server.messages) == 2)
        assert server.messages == [(1, 0, bytes([255, 0, 0, 128, 0, 0, 0, 0, 0])),
                                   (2, 0, bytes([0, 0, 51, 0, 0, 255]))]
        net.close()
        assert wait_for(lambda: len(server.messages) == 4)
        assert server.pixels_of(1).tolist() == [[0, 0, 0]] * 3      # LEDs off
        assert server.pixels_of(2).tolist() == [[0, 0, 0]] * 2


def test_a_channel_whose_inputs_have_no_value_from_their_source_yet_is_not_sent(tmp_path):
    with VirtualOPCServer() as server:
        body = ('<module class="Constant" name="R" data="1"/>\n<module class="Scale" name="S" factor="1"/>\n'
                f'<module class="FadeCandy" name="LED" address="{server.path}" start_server="no">'
                '<channel name="EYES" channel="0" size="1"/></module>\n'
                '<connection source="R.OUTPUT" target="S.INPUT"/>\n'
                '<connection source="S.OUTPUT" target="LED.EYES_RED"/>')
        net = load_body(tmp_path, body)
        try:
            net.step()
            net.step()
            net.step()                                  # the value arrives on tick 2
            assert wait_for(lambda: len(server.messages) >= 1)
            assert server.messages == [(0, 0, bytes([255, 0, 0]))]
        finally:
            net.close()


def test_the_documented_channel_0_lights_the_board_and_channel_1_does_not(tmp_path):
    """fcserver's built-in map takes OPC channel 0 only (pixels 0..511 on the eight outputs;
    Fadecandy examples/config/default.json): the docs' example uses channel 0."""
    with VirtualOPCServer() as server:
        for number in (1, 0):
            net = model(tmp_path, server.path, channels=f'<channel name="EYES" channel="{number}" size="3"/>'
                                                        '<channel name="MOUTH" channel="9" size="2"/>')
            try:
                net.step()
                assert wait_for(lambda: any(c == number for c, _, _ in server.messages))
                lit = [[255, 0, 0], [128, 0, 0], [0, 0, 0]] if number == 0 else [[0, 0, 0]] * 3
                assert server.board_pixels(3).tolist() == lit
            finally:
                net.close()


def test_the_simulated_server_from_the_address(tmp_path):
    net = model(tmp_path, "sim:opc")
    try:
        net.step()
        server = net.modules["LED"].module._simulator
        assert wait_for(lambda: 2 in server.pixels)
        assert server.pixels_of(2).tolist() == [[0, 0, 51], [0, 0, 255]]
    finally:
        net.close()


def test_a_lost_server_stops_the_run_with_its_address(tmp_path):
    server = VirtualOPCServer().start()
    net = model(tmp_path, server.path)
    server.disconnect()
    with pytest.raises(RunError, match=f"OPC server at {server.path} is lost"):
        for _ in range(50):
            net.step()
            time.sleep(0.01)
    net.close()


def test_start_server_runs_the_program_and_stops_it(tmp_path):
    with socket.socket() as probe:                       # a free port for the fake server
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    program = tmp_path / "fake-fcserver"
    marker = tmp_path / "stopped"
    program.write_text(
        f"#!{sys.executable}\n"
        "import signal, sys, time\n"
        "from ikaros.hardware.opc_sim import VirtualOPCServer\n"
        f"signal.signal(signal.SIGTERM, lambda *a: (open({str(marker)!r}, 'w').close(), "
        "sys.exit(0)))\n"                                  # before the port opens: a busy machine
        f"server = VirtualOPCServer({port}).start()\n"
        "time.sleep(30)\n")
    os.chmod(program, 0o755)
    net = model(tmp_path, f"127.0.0.1:{port}", f'command="{program}"')
    try:
        net.step()
    finally:
        net.close()
    assert marker.exists()


@pytest.mark.parametrize("attribute", ["server", "command"])     # command: Ikaros 2's name
def test_a_missing_program_is_a_warning_and_no_server_an_error(tmp_path, capsys, attribute):
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    with pytest.raises(ModelError, match=f"cannot connect to the OPC server at 127.0.0.1:{port}"):
        model(tmp_path, f"127.0.0.1:{port}", f'{attribute}="no-such-fcserver"')
    assert "'no-such-fcserver' is not installed" in capsys.readouterr().err


@pytest.mark.parametrize("channels, message", [
    ('<channel name="A" channel="x" size="3"/>', "whole-number channel and size"),
    ('<channel name="A" channel="300" size="3"/>', "channel in 0..255"),
    ('<channel name="EYES" channel="1" size="5"/><channel name="MOUTH" channel="2" size="2"/>',
     "EYES_RED has 3 values; channel EYES has 5")])
def test_bad_channels_are_named(tmp_path, channels, message):
    with VirtualOPCServer() as server:
        with pytest.raises(ModelError, match=message):
            model(tmp_path, server.path, channels=channels)


def test_a_script_that_never_closes_turns_the_leds_off(tmp_path):
    with VirtualOPCServer() as server:
        model(tmp_path, server.path).close()                  # writes model.ikg
        assert wait_for(lambda: len(server.messages) == 2)
        server.messages.clear()
        script = tmp_path / "script.py"
        script.write_text("import sys, ikaros\n"
                          f"net = ikaros.load({str(tmp_path / 'model.ikg')!r})\n"
                          "net.step()\n"
                          "sys.exit(0)\n")                     # no close(): the exit hook runs
        result = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                                timeout=60)
        assert result.returncode == 0, result.stderr
        assert wait_for(lambda: len(server.messages) == 4)
        assert server.messages[0][2] == bytes([255, 0, 0, 128, 0, 0, 0, 0, 0])
        assert server.pixels_of(1).tolist() == [[0, 0, 0]] * 3
        assert server.pixels_of(2).tolist() == [[0, 0, 0]] * 2


EPI_BODY = ('<module class="Constant" name="Left" data="1 0 0"/>\n'
            '<module class="Constant" name="Right" data="0 0.5 0"/>\n'
            '<module class="Constant" name="High" data="0 0 1; 0 0 1; 1 1 0"/>\n'
            '<module class="Constant" name="Low" data="0.2 0.2 0.2"/>\n'
            '<module class="FadeCandy" name="LED" {params}/>\n'
            '<connection source="Left.OUTPUT" target="LED.LEFT_EYE" delay="0"/>\n'
            '<connection source="Right.OUTPUT" target="LED.RIGHT_EYE" delay="0"/>\n'
            '<connection source="High.OUTPUT" target="LED.MOUTH_HIGH" delay="0"/>\n'
            '<connection source="Low.OUTPUT" target="LED.MOUTH_LOW" delay="0"/>\n')


def test_the_epi_leds_of_ikaros_3_in_simulation(tmp_path):
    """Ikaros 3's inputs: one colour an eye (12 pixels) or mouth row (8), or 3 × N pixels; the
    left eye on strip 0, the right on strip 1, the mouth rows on strips 2 and 3 of channel 0
    (64 pixels a strip: Fadecandy's "Server Configuration", the built-in map)."""
    net = load_body(tmp_path, EPI_BODY.format(params='simulate="yes"'), dialect="3")
    try:
        net.step()
        server = net.modules["LED"].module._simulator
        assert wait_for(lambda: 0 in server.pixels)
        pixels = server.pixels_of(0)
        assert pixels.shape == (200, 3)                                   # up to the last mouth pixel
        assert pixels[0:12].tolist() == [[255, 0, 0]] * 12 and pixels[12:64].sum() == 0
        assert pixels[64:76].tolist() == [[0, 128, 0]] * 12
        assert pixels[128:131].tolist() == [[0, 0, 255], [0, 0, 255], [255, 255, 0]]   # 3 × N: 3 pixels
        assert pixels[131:192].sum() == 0
        assert pixels[192:200].tolist() == [[51, 51, 51]] * 8
    finally:
        net.close()
    assert server.pixels_of(0).sum() == 0                                 # off at the end


def test_the_epi_leds_are_required_in_an_ikaros_3_file_and_optional_in_an_ikaros_2_file(tmp_path):
    with pytest.raises(ModelError, match=r"the input MOUTH_LOW is not connected \(required in an Ikaros 3 file\)"):
        load_body(tmp_path, EPI_BODY.format(params='simulate="yes"').split('<connection source="Low')[0],
                  dialect="3").step()
    with VirtualOPCServer() as server:
        net = model(tmp_path, server.path)                                # Ikaros 2: channels only
        try:
            net.step()
            assert wait_for(lambda: len(server.messages) == 2)
            assert 0 not in server.pixels
        finally:
            net.close()
