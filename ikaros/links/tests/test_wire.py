"""Tests of link messages: arrays of any shape and rank, signatures, bad messages."""
import numpy as np
import pytest

from ikaros.hardware.link.endpoint import check_key, is_loopback, split_address
from ikaros.hardware.link.wire import BadMessage, LinkError, WrongKey, decode, encode


def test_arrays_of_any_shape_rank_and_type_round_trip_with_tick_and_time():
    arrays = [np.arange(24, dtype=np.float32).reshape(2, 3, 4), np.float32([[]]).reshape(0, 3),
              np.array(7.5, dtype=np.float64), np.arange(5, dtype=np.uint8)]
    for key in (None, b"k"):
        header, got = decode(encode({"tick": 12, "time": 3.25}, arrays, key), key)
        assert header["tick"] == 12 and header["time"] == 3.25
        assert len(got) == 4
        for a, b in zip(arrays, got):
            assert a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b)


def test_a_time_stamp_is_added():
    header, _ = decode(encode({"tick": 0}))
    assert header["time"] > 1.7e9


def test_signatures_are_checked():
    frames = encode({"tick": 1}, [np.ones(3, np.float32)], b"right")
    with pytest.raises(WrongKey, match="another key"):
        decode(frames, b"wrong")
    with pytest.raises(WrongKey, match="has none"):
        decode(frames, None)
    with pytest.raises(WrongKey, match="unsigned"):
        decode(encode({"tick": 1}), b"right")
    tampered = list(frames)
    tampered[2] = np.zeros(3, np.float32).tobytes()
    with pytest.raises(WrongKey):
        decode(tampered, b"right")


@pytest.mark.parametrize("frames, message", [
    ([b""], "at least 2 frames"),
    ([b"", b"not json"], "not a link message"),
    ([b"", b'{"arrays": [["<f4", [2]]]}'], "1 arrays announced, 0 sent"),
    ([b"", b'{"arrays": [["<f4", [3]]]}', b"12345678"], "not a link message"),
    ([b"", b'{"arrays": [["|O", [1]]]}', b"12345678"], "object arrays"),
])
def test_bad_messages_are_refused(frames, message):
    with pytest.raises(BadMessage, match=message):
        decode(frames)


def test_addresses_and_keys():
    assert is_loopback("127.0.0.1") and is_loopback("localhost") and is_loopback("::1")
    assert is_loopback("127.1.2.3") and not is_loopback("0.0.0.0")
    assert not is_loopback("*") and not is_loopback("example.org")
    assert split_address("tcp://10.0.0.2:9000", 1) == ("10.0.0.2", 9000)
    assert split_address("host", 9101) == ("host", 9101)
    assert split_address("[::1]:5", 1) == ("::1", 5)
    with pytest.raises(LinkError, match="port"):
        split_address("host:99999", 1)
    check_key("127.0.0.1", None, "x")
    check_key("10.0.0.2", b"k", "x")
    with pytest.raises(LinkError, match="needs a shared key"):
        check_key("10.0.0.2", None, "the address")
