"""The message format between the kernel and a worker."""
import io
import os

import numpy as np
import pytest

from ikaros.scripted.protocol import WorkerGone, receive, send


def _round_trip(kind, fields=None, arrays=None):
    buffer = io.BytesIO()
    send(buffer, kind, fields, arrays)
    buffer.seek(0)
    return receive(io.BufferedReader(buffer))


def test_fields_and_arrays_arrive_as_sent():
    arrays = {"in:A": np.arange(6, dtype=np.float32).reshape(2, 3),
              "par:m": np.array([[1.5, 2.5]]),
              "scalar": np.array(7.0, dtype=np.float32),
              "empty": np.zeros((0, 4), dtype=np.float32)}
    header, got = _round_trip("tick", {"tick": 3, "parameters": {"gain": 2.0, "on": True}},
                              arrays)
    assert header == {"kind": "tick", "tick": 3, "parameters": {"gain": 2.0, "on": True}}
    assert list(got) == list(arrays)
    for key, array in arrays.items():
        assert got[key].dtype == array.dtype and got[key].shape == array.shape
        assert np.array_equal(got[key], array)


def test_a_non_contiguous_array_is_sent_in_c_order():
    a = np.arange(12, dtype=np.float32).reshape(3, 4).T
    _, got = _round_trip("x", arrays={"a": a})
    assert np.array_equal(got["a"], a)


def test_messages_follow_each_other_over_a_pipe():
    r, w = os.pipe()
    with os.fdopen(w, "wb") as writer, os.fdopen(r, "rb") as reader:
        send(writer, "log", {"level": "print", "text": "hello"})
        send(writer, "done", None, {"out:A": np.ones(2, np.float32)})
        writer.close()
        assert receive(reader)[0] == {"kind": "log", "level": "print", "text": "hello"}
        header, arrays = receive(reader)
        assert header == {"kind": "done"} and arrays["out:A"].tolist() == [1, 1]
        with pytest.raises(WorkerGone):
            receive(reader)


def test_a_message_cut_short_is_a_closed_pipe():
    buffer = io.BytesIO()
    send(buffer, "done", None, {"out:A": np.ones(100, np.float32)})
    cut = io.BufferedReader(io.BytesIO(buffer.getvalue()[:-10]))
    with pytest.raises(WorkerGone):
        receive(cut)
