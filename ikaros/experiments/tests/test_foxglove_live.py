"""The live Foxglove view: its channel list and one message per channel, read with a
WebSocket client speaking Foxglove's protocol."""
import asyncio
import json
import os
import struct

import numpy as np
import websockets
from rosbags.typesys import Stores, get_typestore

import ikaros
from ikaros.experiments.foxglove_live import FoxgloveView
from ikaros.hardware.ros2 import LOOPBACK

MODEL = """<group tick_duration="0.01">
  <module class="Constant" name="A" data="1, 2, 3"/>
  <module class="Constant" name="B" data="4; 5"/>
</group>"""
STORE = get_typestore(Stores.ROS2_HUMBLE)


async def _listen(port, channels_wanted, ticking, protocol="foxglove.sdk.v1"):
    async with websockets.connect(f"ws://127.0.0.1:{port}", subprotocols=[protocol]) as ws:
        assert ws.subprotocol == protocol
        channels = {}
        while len(channels) < channels_wanted:
            message = json.loads(await ws.recv())
            if message["op"] == "advertise":
                channels.update({c["id"]: c for c in message["channels"]})
        await ws.send(json.dumps({"op": "subscribe", "subscriptions": [
            {"id": k, "channelId": cid} for k, cid in enumerate(channels)]}))
        ids = list(channels)
        got = {}
        while len(got) < len(ids):
            ticking()
            try:
                data = await asyncio.wait_for(ws.recv(), 0.2)
            except asyncio.TimeoutError:
                continue
            if isinstance(data, bytes) and data[0] == 1:      # a message: op, sub, time
                subscription, _ = struct.unpack_from("<IQ", data, 1)
                got[channels[ids[subscription]]["topic"]] = bytes(data[13:])
        return channels, got


def _view_of_model(tmp_path, protocol="foxglove.sdk.v1"):
    """The channels and a message of each that a client naming ``protocol`` gets."""
    path = tmp_path / "m.ikg"
    path.write_text(MODEL)
    with ikaros.load(str(path)) as net:
        view = FoxgloveView(net, port=0, interval=0.0)
        try:
            return asyncio.run(asyncio.wait_for(
                _listen(view.port, 2, lambda: net.run(ticks=1), protocol), 30))
        finally:
            view.close()


def test_the_outputs_are_channels_of_ros_2_messages(tmp_path):
    channels, got = _view_of_model(tmp_path)
    assert sorted((c["topic"], c["encoding"], c["schemaName"], c["schemaEncoding"])
                  for c in channels.values()) == [
        ("/ikaros/A/OUTPUT", "cdr", "std_msgs/msg/Float32MultiArray", "ros2msg"),
        ("/ikaros/B/OUTPUT", "cdr", "std_msgs/msg/Float32MultiArray", "ros2msg")]
    a = STORE.deserialize_cdr(got["/ikaros/A/OUTPUT"], "std_msgs/msg/Float32MultiArray")
    b = STORE.deserialize_cdr(got["/ikaros/B/OUTPUT"], "std_msgs/msg/Float32MultiArray")
    np.testing.assert_array_equal(a.data, [1, 2, 3])
    np.testing.assert_array_equal(b.data, [4, 5])
    assert [(d.size, d.stride) for d in b.layout.dim] == [(2, 2), (1, 1)]


IMAGES = """<group tick_duration="0.01">
  <module class="Constant" name="Picture" data="[[[1, 0]], [[0, 0.5]], [[0, 1]]]"/>
  <module class="Constant" name="Angles" data="0.5, -0.25"/>
  <module class="ROS2Publisher" name="Joints" topic="/joint_states" type="JointState"
          names="shoulder, elbow" domain_id="{domain}"/>
  <connection source="Angles.OUTPUT" target="Joints.INPUT" delay="0"/>
</group>"""


def test_colour_images_and_what_publishers_send_keep_their_ros_types(tmp_path, monkeypatch):
    monkeypatch.setenv("CYCLONEDDS_URI", LOOPBACK)
    path = tmp_path / "m.ikg"
    path.write_text(IMAGES.format(domain=100 + os.getpid() % 100))
    with ikaros.load(str(path)) as net:
        view = FoxgloveView(net, port=0, interval=0.0, only=["Picture.OUTPUT"])
        try:
            channels, got = asyncio.run(asyncio.wait_for(
                _listen(view.port, 2, lambda: net.run(ticks=1)), 30))
        finally:
            view.close()
    assert sorted((c["topic"], c["schemaName"]) for c in channels.values()) == [
        ("/ikaros/Picture/OUTPUT", "sensor_msgs/msg/Image"),
        ("/joint_states", "sensor_msgs/msg/JointState")]
    image = STORE.deserialize_cdr(got["/ikaros/Picture/OUTPUT"], "sensor_msgs/msg/Image")
    assert (image.height, image.width, image.encoding, image.step) == (1, 2, "rgb8", 6)
    assert list(image.data) == [255, 0, 0, 0, 128, 255]     # (r, g, b) of each pixel
    joints = STORE.deserialize_cdr(got["/joint_states"], "sensor_msgs/msg/JointState")
    assert joints.name == ["shoulder", "elbow"]
    np.testing.assert_array_equal(joints.position, [0.5, -0.25])


def test_a_client_of_the_protocols_old_name_connects_too(tmp_path):
    # Foxglove's WebSocket protocol was named foxglove.websocket.v1; older Foxglove and
    # Lichtblick versions offer only that name, which the Foxglove SDK refuses (HTTP 400)
    channels, got = _view_of_model(tmp_path, "foxglove.websocket.v1")
    assert sorted(c["topic"] for c in channels.values()) == ["/ikaros/A/OUTPUT",
                                                            "/ikaros/B/OUTPUT"]
    message = STORE.deserialize_cdr(got["/ikaros/A/OUTPUT"], "std_msgs/msg/Float32MultiArray")
    np.testing.assert_array_equal(message.data, [1, 2, 3])
