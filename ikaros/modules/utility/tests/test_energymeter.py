"""Tests of the EnergyMeter module (Ikaros 3, MODULES-V3 §18), against a status page served
on 127.0.0.1."""
import http.server
import threading

import pytest

from ikaros.testing import load_body as load


@pytest.fixture
def plug():
    pages = ['{"id": 1, "power": 1800.5, "ok": true}', '{"power":2000}', 'nothing']

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_GET(self):
            body = (pages.pop(0) if pages else "{}").encode()
            self.send_response(200)
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, *args):
            pass

    server = http.server.HTTPServer(("127.0.0.1", 0), Handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"127.0.0.1:{server.server_address[1]}/status"
    server.shutdown()
    server.server_close()


def test_power_and_energy_from_the_status_page(tmp_path, plug):
    net = load(tmp_path, f'<module class="EnergyMeter" name="E" address="{plug}" '
                         'timeout="10"/>', tick_duration="0.5")
    try:
        unit = 0.5 / (1000 * 1000 * 3600)
        net.step()
        assert net.output("E.MEASURED_POWER")[0] == pytest.approx(1800.5)
        assert net.output("E.ENERGY")[0] == pytest.approx(1800.5 * unit)
        net.step()
        assert net.output("E.ENERGY")[0] == pytest.approx((1800.5 + 2000) * unit)
        net.step()                  # no power on the page: energy restarts, power is kept
        assert net.output("E.MEASURED_POWER")[0] == 2000
        assert net.output("E.ENERGY")[0] == pytest.approx(2000 * unit)
    finally:
        net.close()
