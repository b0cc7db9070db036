"""A client that sends less body than its Content-Length promised and then goes away is one
line in the server's log, not a traceback (a real server: ``ikaros -w 0``)."""
import os
import signal
import socket
import subprocess
import sys

import pytest

from ikaros.testing import wait_for

pytest.importorskip("uvicorn")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
PATHS = ("/api/apply", "/api/save", "/api/record")


def test_a_client_gone_mid_body_is_one_line_in_the_log(tmp_path):
    model = tmp_path / "m.ikg"
    model.write_text('<group name="M"><module class="Constant" name="C" data="1"/></group>')
    log = tmp_path / "stderr.txt"
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    with open(log, "w") as err:
        server = subprocess.Popen([sys.executable, "-m", "ikaros", "-w", "0", str(model)],
                                  env=env, stdout=subprocess.PIPE, stderr=err, text=True)
    try:
        line = server.stdout.readline()
        assert " at http://127.0.0.1:" in line, line + log.read_text()
        port = int(line.split(" at http://127.0.0.1:")[1].split("/")[0])
        for path in PATHS:
            with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
                s.sendall(f"POST {path} HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: "
                          f"application/json\r\nContent-Length: 1000\r\n\r\n"
                          f'{{"tree": '.encode())
        expected = [f"ikaros: web UI: POST {path}: the client went away before sending the "
                    f"whole request" for path in PATHS]
        assert wait_for(lambda: sorted(log.read_text().splitlines()) == sorted(expected),
                        60, 0.05), log.read_text()
    finally:
        server.send_signal(signal.SIGINT)
        try:
            server.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
            server.communicate()
    assert "Traceback" not in log.read_text()
