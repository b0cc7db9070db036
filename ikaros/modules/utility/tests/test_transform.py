"""Tests of the Transform module."""
import numpy as np
import pytest

import ikaros

from ikaros.testing import load_body as load


def rigid(angle, t):
    c, s = np.cos(angle), np.sin(angle)
    m = np.eye(4)
    m[:2, :2] = [[c, -s], [s, c]]
    m[:3, 3] = t
    return m


def constant(name, data):
    data = np.atleast_2d(data)
    text = "; ".join(" ".join(f"{v:.9g}" for v in row) for row in data)
    return f'<module class="Constant" name="{name}" data="{text}"/>\n'


def model(m1, o1, f1, m2, o2, f2, **params):
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = (constant("M1", [m.reshape(-1) for m in m1]) + constant("O1", [o1]) +
            constant("F1", [f1]) + constant("M2", [m.reshape(-1) for m in m2]) +
            constant("O2", [o2]) + constant("F2", [f2]) +
            f'<module class="Transform" name="T" {attrs}/>\n')
    for a, b in (("M1", "MATRIX_1"), ("O1", "OBJECT_ID_1"), ("F1", "FRAME_ID_1"),
                 ("M2", "MATRIX_2"), ("O2", "OBJECT_ID_2"), ("F2", "FRAME_ID_2")):
        body += f'<connection source="{a}.OUTPUT" target="T.{b}" delay="0"/>\n'
    return body


A = [rigid(0.3, [1, 2, 0]), rigid(-1.0, [0, 0, 1]), np.zeros((4, 4))]
B = [rigid(0.5, [3, 0, 0]), rigid(2.0, [0, 1, 1])]


def test_matching_pairs_are_multiplied(tmp_path):
    # list 1: objects 10, 11, (invalid 12) in frame 0; list 2: objects 20, 21 in frames 11, 10
    net = load(tmp_path, model(A, [10, 11, 12], [0, 0, 0], B, [20, 21], [11, 10]))
    try:
        assert net.output("T.MATRIX").shape == (3, 16)
        for _ in range(2):
            net.step()
            m = net.output("T.MATRIX").reshape(3, 4, 4)
            # pairs in order of i then j: (0, 1) since 10 == F2[1]; (1, 0) since 11 == F2[0]
            assert np.allclose(m[0], A[0] @ B[1], atol=1e-5)
            assert np.allclose(m[1], A[1] @ B[0], atol=1e-5)
            assert np.array_equal(m[2], np.zeros((4, 4)))
            assert np.array_equal(net.output("T.OBJECT_ID"), [21, 20, 0])
            assert np.array_equal(net.output("T.FRAME_ID"), [0, 0, 0])
    finally:
        net.close()


def test_invert_2_expresses_list_2_in_list_1_objects_frame(tmp_path):
    # Inverted, matrix k of list 2 places its frame 5 in the frame of its object k, so it
    # matches list 1's object k; the product places frame 5 in list 1's frame 0.
    net = load(tmp_path, model(A[:2], [1, 2], [0, 0], B, [1, 2], [5, 5], invert_2="yes"))
    try:
        net.step()
        m = net.output("T.MATRIX").reshape(2, 4, 4)
        assert np.allclose(m[0], A[0] @ np.linalg.inv(B[0]), atol=1e-5)
        assert np.allclose(m[1], A[1] @ np.linalg.inv(B[1]), atol=1e-5)
        assert np.array_equal(net.output("T.OBJECT_ID"), [5, 5])
        assert np.array_equal(net.output("T.FRAME_ID"), [0, 0])
    finally:
        net.close()


def test_invert_1_and_too_many_matches(tmp_path):
    # Inverting list 1 swaps its ids: object 0 in frame 10 -> object id 0 matches both
    # frames 0 of list 2; 2 x 2 = 4 matches for 2 output rows: 2 kept, one warning.
    net = load(tmp_path, model(A[:2], [10, 11], [0, 0], B, [20, 21], [0, 0], invert_1="yes"))
    try:
        net.run(ticks=3)
        m = net.output("T.MATRIX").reshape(2, 4, 4)
        assert np.allclose(m[0], np.linalg.inv(A[0]) @ B[0], atol=1e-5)
        assert np.allclose(m[1], np.linalg.inv(A[0]) @ B[1], atol=1e-5)
        assert np.array_equal(net.output("T.OBJECT_ID"), [20, 21])
        assert np.array_equal(net.output("T.FRAME_ID"), [10, 10])
        warnings = [m for (_, level, where, m) in net.log if where == "T" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()


def test_no_match_gives_zero(tmp_path):
    net = load(tmp_path, model(A, [1, 2, 3], [0, 0, 0], B, [4, 5], [7, 8]))
    try:
        net.step()
        assert not net.output("T.MATRIX").any()
        assert not net.output("T.OBJECT_ID").any()
    finally:
        net.close()


def test_an_incomplete_matrix_list_as_ikaros_2_and_3(tmp_path):
    # golden-v2 Transform "vector": 4-element inputs hold no whole matrix; the outputs stay 0
    body = model([np.arange(4.0)], [1], [2], [np.arange(4.0)], [1], [2])
    body = body.replace('data="0 1 2 3"', 'data="0.5 -1 2 0.25"')
    with load(tmp_path, body) as net:
        net.step()
        assert net.output("T.MATRIX").shape == (1, 16)
        assert not net.output("T.MATRIX").any() and not net.output("T.FRAME_ID").any()
        assert sum("not a multiple of 16" in entry[3] for entry in net.log) == 2
    with pytest.raises(ikaros.ModelError, match="16 elements"):
        load(tmp_path, body, dialect="3")
