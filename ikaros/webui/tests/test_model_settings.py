"""The web UI's top-group settings webui_req_int and webui_log_buffer_limit
(webui/settings.py)."""
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

from ikaros.module import WARNING  # noqa: E402
from ikaros.testing import load_body  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

BODY = '<module class="Constant" name="C" data="1"/>'


def status_of(net, **kwargs):
    with TestClient(create_app(net, **kwargs)) as c:
        return c.get("/api/status").json()


def test_the_defaults_without_settings(tmp_path):
    net = load_body(tmp_path, BODY)
    status = status_of(net)
    assert status["webui_req_int"] == pytest.approx(1 / 15)
    assert status["webui_log_buffer_limit"] == 1000
    net.close()


def test_the_settings_of_the_top_group(tmp_path):
    net = load_body(tmp_path, BODY, webui_req_int="0.5", webui_log_buffer_limit="3")
    status = status_of(net)
    assert (status["webui_req_int"], status["webui_log_buffer_limit"]) == (0.5, 3)
    net.close()


def test_max_rate_given_to_the_app_wins(tmp_path):
    net = load_body(tmp_path, BODY, webui_req_int="0.5")
    assert status_of(net, max_rate=4.0)["webui_req_int"] == 0.25
    net.close()


def test_the_log_keeps_the_latest_messages(tmp_path):
    net = load_body(tmp_path, BODY, webui_log_buffer_limit="2")
    for text in ["one", "two", "three"]:
        net.notify(WARNING, None, text)
    with TestClient(create_app(net)) as c:
        answer = c.get("/api/log").json()
    assert [m["message"] for m in answer["messages"]] == ["two", "three"]
    assert answer["next"] == 3
    net.close()


@pytest.mark.parametrize("key, text, default, rule", [
    ("webui_req_int", "-1", 1 / 15, "a number of seconds >= 0; the web UI uses 0.0666667"),
    ("webui_req_int", "fast", 1 / 15, "a number of seconds >= 0"),
    ("webui_log_buffer_limit", "0", 1000, "a whole number >= 1; the web UI uses 1000"),
    ("webui_log_buffer_limit", "2.5", 1000, "a whole number >= 1")])
def test_a_bad_value_is_a_warning_and_the_default_is_used(tmp_path, key, text, default, rule):
    net = load_body(tmp_path, BODY, **{key: text})
    assert status_of(net)[key] == pytest.approx(default)
    warnings_ = [m for _, level, _, m in net.log if level == WARNING]
    assert len(warnings_) == 1 and warnings_[0].startswith(f'{key}="{text}" must be {rule}')
    net.close()


def test_the_jpeg_qualities_of_colour_and_gray_images(tmp_path):
    net = load_body(tmp_path, BODY, rgb_quality="13", gray_quality="17")
    status = status_of(net)
    assert (status["rgb_quality"], status["gray_quality"]) == (13, 17)
    net.close()
    net = load_body(tmp_path, BODY, rgb_quality="0", gray_quality="101")
    status = status_of(net)
    assert (status["rgb_quality"], status["gray_quality"]) == (85, 85)
    warnings_ = [m for _, level, _, m in net.log if level == WARNING]
    assert warnings_ == ['rgb_quality="0" must be a whole number from 1 to 100; the web UI '
                         'uses 85', 'gray_quality="101" must be a whole number from 1 to '
                         '100; the web UI uses 85']
    net.close()


def test_a_jpeg_image_is_encoded_at_the_quality_given():
    import io

    import numpy as np
    from PIL import Image

    from ikaros.webui.encoding import encode_array
    a = np.random.default_rng(1).random((3, 32, 32))
    low, default = encode_array(a, "jpeg", 13), encode_array(a, "jpeg")
    pixels = (np.clip(a, 0, 1) * 255 + 0.5).astype(np.uint8).transpose(1, 2, 0)
    expected = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(pixels), "RGB").save(expected, "JPEG", quality=13)
    # the quantisation tables are what the quality sets (OpenCV or Pillow encodes)
    assert Image.open(io.BytesIO(low)).quantization == Image.open(expected).quantization
    assert len(low) < len(default)


def test_the_frames_carry_jpeg_images_at_the_models_qualities(tmp_path):
    from ikaros.webui.encoding import decode_frame, encode_array
    body = ('<module class="Constant" name="Gray" data="0 0.5; 1 0.25"/>\n'
            '<module class="Constant" name="Rgb" '
            'data="[[[1, 0], [0, 1]], [[0, 1], [0, 1]], [[0, 0], [1, 1]]]"/>')
    net = load_body(tmp_path, body, rgb_quality="13", gray_quality="17")
    with TestClient(create_app(net)) as client, client.websocket_connect("/api/ws") as ws:
        ws.send_json({"type": "subscribe", "buffers": [
            {"path": "Gray.OUTPUT", "format": "jpeg"}, {"path": "Rgb.OUTPUT", "format": "jpeg"}]})
        ws.send_json({"type": "ready"})
        while True:
            m = ws.receive()
            if m.get("bytes") is not None:
                header, data = decode_frame(m["bytes"])
                break
    gray, rgb = net.buffer_array("Gray.OUTPUT"), net.buffer_array("Rgb.OUTPUT")
    assert data["Gray.OUTPUT"] == encode_array(gray, "jpeg", 17)
    assert data["Gray.OUTPUT"] != encode_array(gray, "jpeg", 13)
    assert rgb.shape == (3, 2, 2)
    assert data["Rgb.OUTPUT"] == encode_array(rgb, "jpeg", 13)
    assert data["Rgb.OUTPUT"] != encode_array(rgb, "jpeg", 17)
    net.close()
