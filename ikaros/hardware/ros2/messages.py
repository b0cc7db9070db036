"""The ROS 2 messages ikaros publishes and subscribes to, as plain dicts with NumPy arrays,
to and from their CDR bytes (cdr.py). Field names and order are those of the ROS 2 message
definitions (msgdefs.py holds their text)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from .cdr import Decoder, Encoder


@dataclass(frozen=True)
class MessageType:
    """A ROS 2 message type: ``name`` as ROS writes it (``std_msgs/msg/Float32``)."""
    name: str
    encode: Callable[[dict], bytes]
    decode: Callable[[bytes], dict]

    @property
    def dds_name(self) -> str:
        """The DDS type name ROS 2 gives it: ``std_msgs::msg::dds_::Float32_``."""
        package, _, message = self.name.split("/")
        return f"{package}::msg::dds_::{message}_"


def stamp(seconds: float) -> tuple[int, int]:
    """A time in seconds as builtin_interfaces/Time's (sec, nanosec)."""
    nanoseconds = int(round(seconds * 1e9))
    return nanoseconds // 1_000_000_000, nanoseconds % 1_000_000_000


def _put_header(e: Encoder, header: dict) -> None:
    sec, nanosec = header.get("stamp", (0, 0))
    e.primitive("i", sec)
    e.primitive("I", nanosec)
    e.string(header.get("frame_id", ""))


def _get_header(d: Decoder) -> dict:
    sec = d.primitive("i")
    return {"stamp": (sec, d.primitive("I")), "frame_id": d.string()}


def _scalar(fmt: str, dtype: str):
    def encode(m: dict) -> bytes:
        e = Encoder()
        e.primitive(fmt, np.asarray(m["data"], dtype).item())
        return e.bytes()

    def decode(data: bytes) -> dict:
        return {"data": Decoder(data).primitive(fmt)}
    return encode, decode


def _multi_array(dtype: str):
    def encode(m: dict) -> bytes:
        e = Encoder()
        layout = m.get("layout", {})
        dims = layout.get("dim", [])
        e.primitive("I", len(dims))
        for dim in dims:
            e.string(dim.get("label", ""))
            e.primitive("I", dim["size"])
            e.primitive("I", dim["stride"])
        e.primitive("I", layout.get("data_offset", 0))
        e.sequence(m["data"], dtype)
        return e.bytes()

    def decode(data: bytes) -> dict:
        d = Decoder(data)
        dims = []
        for _ in range(d.primitive("I")):
            label = d.string()
            size = d.primitive("I")
            dims.append({"label": label, "size": size, "stride": d.primitive("I")})
        offset = d.primitive("I")
        return {"layout": {"dim": dims, "data_offset": offset}, "data": d.sequence(dtype)}
    return encode, decode


def layout_of(shape: tuple[int, ...], labels: tuple[str, ...] = ()) -> dict:
    """A MultiArrayLayout for a C-ordered array of ``shape`` (ROS's row-major convention:
    each dimension's stride is the number of elements it spans)."""
    dims, stride = [], int(np.prod(shape, dtype=np.int64)) if shape else 1
    for i, size in enumerate(shape):
        dims.append({"label": labels[i] if i < len(labels) else f"dim{i}", "size": int(size),
                     "stride": int(stride)})
        stride //= max(int(size), 1)
    return {"dim": dims, "data_offset": 0}


def float32_array_encoder(shape: tuple[int, ...]) -> Callable[[np.ndarray], bytes]:
    """A fast encoder of the std_msgs/Float32MultiArray messages of arrays of ``shape``:
    their bytes up to the values are the same every time (the data is 4-aligned after
    them), so a message is that prefix and the values' bytes."""
    count = int(np.prod(shape, dtype=np.int64)) if shape else 1
    empty = TYPES["std_msgs/msg/Float32MultiArray"].encode({"layout": layout_of(shape),
                                                            "data": []})
    prefix = empty[:-4] + count.to_bytes(4, "little")

    def encode(values: np.ndarray) -> bytes:
        return prefix + np.ascontiguousarray(values, "<f4").tobytes()
    return encode


def _encode_twist(m: dict) -> bytes:
    e = Encoder()
    for part in ("linear", "angular"):
        for value in m[part]:
            e.primitive("d", float(value))
    return e.bytes()


def _decode_twist(data: bytes) -> dict:
    d = Decoder(data)
    return {part: tuple(d.primitive("d") for _ in range(3)) for part in ("linear", "angular")}


def _encode_joint_state(m: dict) -> bytes:
    e = Encoder()
    _put_header(e, m.get("header", {}))
    e.strings(m.get("name", []))
    for field in ("position", "velocity", "effort"):
        e.sequence(m.get(field, ()), "<f8")
    return e.bytes()


def _decode_joint_state(data: bytes) -> dict:
    d = Decoder(data)
    out = {"header": _get_header(d), "name": d.strings()}
    for field in ("position", "velocity", "effort"):
        out[field] = d.sequence("<f8")
    return out


def _encode_image(m: dict) -> bytes:
    e = Encoder()
    _put_header(e, m.get("header", {}))
    e.primitive("I", m["height"])
    e.primitive("I", m["width"])
    e.string(m["encoding"])
    e.primitive("B", m.get("is_bigendian", 0))
    e.primitive("I", m["step"])
    e.raw(m["data"])
    return e.bytes()


def _decode_image(data: bytes) -> dict:
    d = Decoder(data)
    out = {"header": _get_header(d), "height": d.primitive("I"), "width": d.primitive("I"),
           "encoding": d.string(), "is_bigendian": d.primitive("B"), "step": d.primitive("I")}
    out["data"] = d.raw()
    return out


TYPES: dict[str, MessageType] = {t.name: t for t in (
    MessageType("std_msgs/msg/Float32", *_scalar("f", "<f4")),
    MessageType("std_msgs/msg/Float64", *_scalar("d", "<f8")),
    MessageType("std_msgs/msg/Float32MultiArray", *_multi_array("<f4")),
    MessageType("std_msgs/msg/Float64MultiArray", *_multi_array("<f8")),
    MessageType("geometry_msgs/msg/Twist", _encode_twist, _decode_twist),
    MessageType("sensor_msgs/msg/JointState", _encode_joint_state, _decode_joint_state),
    MessageType("sensor_msgs/msg/Image", _encode_image, _decode_image),
)}


def message_type(name: str) -> MessageType:
    """A supported type by its ROS name, with or without ``/msg/``
    (``std_msgs/Float32`` or ``std_msgs/msg/Float32``)."""
    parts = name.strip().split("/")
    full = "/".join((parts[0], "msg", parts[-1])) if len(parts) in (2, 3) else name
    if full not in TYPES:
        raise KeyError(f'the message type "{name}" is not supported (supported: '
                       f'{", ".join(sorted(TYPES))})')
    return TYPES[full]
