"""Tests of the KalmanFilter module."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.module import WARNING
from ikaros.testing import load_body as load


def reference(A, B, H, q, r, us, zs):
    """The textbook filter in float64: (state, innovation, gain) after each observation."""
    n, m = A.shape[0], H.shape[0]
    x, P = np.zeros(n), np.eye(n)
    out = []
    for u, z in zip(us, zs):
        x = A @ x + (B @ u if B is not None else 0)
        P = A @ P @ A.T + q * np.eye(n)
        y = z - H @ x
        S = H @ P @ H.T + r * np.eye(m)
        K = P @ H.T @ np.linalg.inv(S)
        x = x + K @ y
        P = (np.eye(n) - K @ H) @ P
        out.append((x, y, K))
    return out


def data_file(tmp_path, columns, rows):
    header = " ".join(f"{name}/{n}" for name, n in columns)
    body = "\n".join(" ".join(str(v) for v in row) for row in rows)
    (tmp_path / "d.txt").write_text(header + "\n" + body + "\n")


def test_scalar_defaults_hand_worked(tmp_path):
    data_file(tmp_path, [("Z", 1)], [[3], [3]])
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K" default_matrices="identity"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')
    try:
        assert net.output("K.STATE").shape == (1,)
        assert net.output("K.KALMAN_GAIN").shape == (1, 1)
        net.step()
        # A = H = 1, Q = R = 1, P = 1: P' = 2, S = 3, K = 2/3, x = 2/3 * 3 = 2, P = 2/3
        assert np.allclose(net.output("K.KALMAN_GAIN"), [[2 / 3]])
        assert np.allclose(net.output("K.STATE"), [2])
        assert np.allclose(net.output("K.INNOVATION"), [3])
        net.step()
        # P' = 5/3, S = 8/3, K = 5/8, y = 3 - 2 = 1, x = 2 + 5/8
        assert np.allclose(net.output("K.KALMAN_GAIN"), [[5 / 8]])
        assert np.allclose(net.output("K.INNOVATION"), [1])
        assert np.allclose(net.output("K.STATE"), [2.625])
    finally:
        net.close()


def test_constant_velocity_with_control_input(tmp_path):
    rng = np.random.default_rng(3)
    us = rng.normal(size=(10, 1)).round(3)
    zs = (np.arange(10) * 0.5 + rng.normal(scale=0.2, size=10)).round(3).reshape(10, 1)
    data_file(tmp_path, [("U", 1), ("Z", 1)], np.hstack([us, zs]))
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K" state_size="2" '
                         'A="1 1; 0 1" B="0.5; 1" H="1 0" process_noise="0.01" '
                         'observation_noise="0.04"/>\n'
                         '<connection source="D.U" target="K.INPUT" delay="0"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')
    A = np.array([[1.0, 1], [0, 1]])
    B = np.array([[0.5], [1.0]])
    H = np.array([[1.0, 0]])
    try:
        assert net.output("K.KALMAN_GAIN").shape == (2, 1)
        for x, y, K in reference(A, B, H, 0.01, 0.04, us, zs):
            net.step()
            assert np.allclose(net.output("K.STATE"), x, atol=1e-4)
            assert np.allclose(net.output("K.INNOVATION"), y, atol=1e-4)
            assert np.allclose(net.output("K.KALMAN_GAIN"), K, atol=1e-5)
    finally:
        net.close()


def test_two_observations_flat_matrices_and_no_input(tmp_path):
    zs = np.array([[1, 2], [1.5, 1], [0.5, -1], [2, 2]])
    data_file(tmp_path, [("Z", 2)], zs)
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K" state_size="3" '
                         'observation_size="2" A="0.9 0 0 0 1 0 0.1 0 0.5" '
                         'H="1 0 0 0 1 1" process_noise="0.5" observation_noise="2"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')
    A = np.array([[0.9, 0, 0], [0, 1, 0], [0.1, 0, 0.5]])
    H = np.array([[1.0, 0, 0], [0, 1, 1]])
    try:
        assert net.output("K.KALMAN_GAIN").shape == (3, 2)
        for x, y, K in reference(A, None, H, 0.5, 2, [None] * 4, zs):
            net.step()
            assert np.allclose(net.output("K.STATE"), x, atol=1e-5)
            assert np.allclose(net.output("K.INNOVATION"), y, atol=1e-5)
            assert np.allclose(net.output("K.KALMAN_GAIN"), K, atol=1e-5)
    finally:
        net.close()


def test_singular_innovation_covariance_keeps_the_prediction(tmp_path):
    data_file(tmp_path, [("Z", 1)], [[1], [2], [3]])
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="Constant" name="U" data="1"/>\n'
                         '<module class="KalmanFilter" name="K" H="0" B="1" A="1" '
                         'observation_noise="0"/>\n'
                         '<connection source="U.OUTPUT" target="K.INPUT" delay="0"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')
    try:
        for tick in range(3):
            net.step()
            assert np.all(np.isfinite(net.output("K.STATE")))
            assert net.output("K.STATE")[0] == tick + 1          # x' = x + u, no correction
            assert net.output("K.KALMAN_GAIN")[0, 0] == 0
        warnings = [e for e in net.log if e[1] == WARNING and "singular" in e[3]]
        assert len(warnings) == 1
    finally:
        net.close()


def test_observation_size_must_match(tmp_path):
    data_file(tmp_path, [("Z", 2)], [[1, 2]])
    with pytest.raises(ModelError, match="observation_size is 1"):
        load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                       '<module class="KalmanFilter" name="K"/>\n'
                       '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')


def test_bad_matrix_shape_is_a_build_error(tmp_path):
    data_file(tmp_path, [("Z", 1)], [[1]])
    with pytest.raises(ModelError, match="A has shape"):
        load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                       '<module class="KalmanFilter" name="K" state_size="2" A="1 2 3"/>\n'
                       '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')


# --- the optional inputs in an Ikaros 2 file: ENABLE, INPUT_VALID, OBSERVATION_VALID, RESET ---
# Scalar filter, A = H = 1, Q = R = 1, observation 3 every tick: a normal first tick gives
# K = 2/3, x = 2 (P = 2/3), a normal second tick K = 5/8, x = 2.625.

def run_v3(tmp_path, columns, rows, attrs="", links=()):
    """Steps through the rows; returns (STATE, INNOVATION, KALMAN_GAIN) after each tick."""
    data_file(tmp_path, columns, rows)
    body = ('<module class="InputFile" name="D" filename="d.txt"/>\n'
            f'<module class="KalmanFilter" name="K" default_matrices="identity" {attrs}/>\n'
            '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>\n' +
            "".join(f'<connection source="D.{a}" target="K.{b}" delay="0"/>\n'
                    for a, b in links))
    net = load(tmp_path, body, dialect=2)    # Ikaros 2's filter, with Ikaros 3's inputs
    out = []
    try:
        for _ in rows:
            net.step()
            out.append(tuple(net.output(f"K.{n}").astype(float).tolist()
                             for n in ("STATE", "INNOVATION", "KALMAN_GAIN")))
    finally:
        net.close()
    return out


def test_enable_holds_the_filter(tmp_path):
    out = run_v3(tmp_path, [("Z", 1), ("G", 1)], [[3, 1], [3, 0], [3, 1]],
                 links=[("G", "ENABLE")])
    assert np.allclose(out[0][0], [2]) and np.allclose(out[1][0], [2])
    assert np.allclose(out[1][2], [[2 / 3]])              # held from tick 0
    assert np.allclose(out[2][0], [2.625]) and np.allclose(out[2][2], [[5 / 8]])


def test_reset_restarts_the_state(tmp_path):
    out = run_v3(tmp_path, [("Z", 1), ("R", 1)], [[3, 0], [3, 1], [3, 0]],
                 links=[("R", "RESET")])
    assert np.allclose(out[1][0], [2]) and np.allclose(out[1][2], [[2 / 3]])
    assert np.allclose(out[1][1], [3])
    assert np.allclose(out[2][0], [2.625])


def test_observation_valid_zero_is_a_prediction_only(tmp_path):
    out = run_v3(tmp_path, [("Z", 1), ("V", 1)], [[3, 0], [3, 1]],
                 links=[("V", "OBSERVATION_VALID")])
    assert out[0] == ([0.0], [0.0], [[0.0]])
    # P = 2 after the prediction-only tick: P' = 3, S = 4, K = 3/4, x = 3/4 * 3
    assert np.allclose(out[1][2], [[0.75]]) and np.allclose(out[1][0], [2.25])


def test_observation_valid_per_element(tmp_path):
    out = run_v3(tmp_path, [("Z", 2), ("V", 2)], [[3, 5, 1, 0]],
                 attrs='observation_size="2" H="1; 1"', links=[("V", "OBSERVATION_VALID")])
    state, innovation, gain = out[0]
    assert np.allclose(state, [2]) and np.allclose(innovation, [3, 0])
    assert np.allclose(gain, [[2 / 3, 0]])


def test_input_valid_leaves_the_control_input_out(tmp_path):
    out = run_v3(tmp_path, [("Z", 1), ("U", 1), ("I", 1)], [[3, 1, 0], [3, 1, 1]],
                 attrs='B="1"', links=[("U", "INPUT"), ("I", "INPUT_VALID")])
    assert np.allclose(out[0][0], [2])                    # as without INPUT
    # x' = 2 + 1 = 3, P' = 2/3 + 1, S = 8/3, K = 5/8, y = 3 - 3 = 0
    assert np.allclose(out[1][0], [3]) and np.allclose(out[1][2], [[5 / 8]])


def test_observation_valid_of_wrong_size_is_an_error(tmp_path):
    with pytest.raises(ModelError, match="OBSERVATION_VALID has 3 elements"):
        run_v3(tmp_path, [("Z", 1), ("V", 3)], [[3, 1, 1, 1]],
               links=[("V", "OBSERVATION_VALID")])


def test_ikaros_2_file_has_the_ikaros_3_outputs_and_gate(tmp_path):
    # scalar filter, A = H = Q = R = 1, P = I at the start: tick 0, z = 3: S = 3, y = 3,
    # y²/S = 3, K = 2/3, x = 2, P = 2/3; tick 1, z = 9: S = 8/3, y = 7, y²/S = 18.375 > 10:
    # rejected, x = 2 (prediction), P = 5/3; tick 2, z = 3: P' = 8/3, S = 11/3, y = 1,
    # y²/S = 3/11, K = 8/11, x = 2 + 8/11
    data_file(tmp_path, [("Z", 1)], [[3], [9], [3]])
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K" A="1" H="1" '
                         'innovation_gate="10"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')
    expected = [(2, 2 / 3, 0, 3), (2, 0, 1, 18.375), (2 + 8 / 11, 8 / 11, 0, 3 / 11)]
    try:
        for state, gain, gated, normalized in expected:
            net.step()
            assert net.output("K.STATE")[0] == pytest.approx(state, rel=1e-6)
            assert net.output("K.KALMAN_GAIN")[0, 0] == pytest.approx(gain, rel=1e-6)
            assert net.output("K.GATED")[0] == gated
            assert net.output("K.NORMALIZED_INNOVATION")[0] == pytest.approx(normalized,
                                                                             rel=1e-6)
    finally:
        net.close()


# --- Ikaros 3 files (dialect 3): MODULES-V3 §25 -------------------------------------------


def reference_v3(A, H, Q, R, zs, gate=0.0):
    """Ikaros 3's filter, from the reference: Joseph form, an innovation gate, P starts at I."""
    n = A.shape[0]
    x, P = np.zeros(n), np.eye(n)
    out = []
    for z in zs:
        xp, Pp = A @ x, A @ P @ A.T + Q
        y = z - H @ xp
        S = H @ Pp @ H.T + R
        nis = float(y @ np.linalg.inv(S) @ y)
        if gate > 0 and nis > gate:
            x, P, K, gated = xp, Pp, np.zeros((n, len(z))), 1
        else:
            K = Pp @ H.T @ np.linalg.inv(S)
            x = xp + K @ y
            J = np.eye(n) - K @ H
            P = J @ Pp @ J.T + K @ R @ K.T
            gated = 0
        out.append((x, y, K, gated, nis))
    return out


def test_v3_gate_joseph_form_and_process_noise_per_second(tmp_path):
    zs = [[1.0], [1.5], [9.0], [2.4], [3.1]]
    data_file(tmp_path, [("Z", 1)], zs)
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K" state_size="2" '
                         'A="1, 0.5; 0, 1" H="1, 0" process_noise="0.4" '
                         'observation_noise="0.3" innovation_gate="6"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>',
               dialect="3", tick_duration="0.5")
    expected = reference_v3(np.array([[1, 0.5], [0, 1]]), np.array([[1.0, 0]]),
                            0.4 * 0.5 * np.eye(2), 0.3 * np.eye(1), np.array(zs), gate=6)
    try:
        assert net.output("K.KALMAN_GAIN").shape == (2, 1)
        gates = []
        for x, y, K, gated, nis in expected:
            net.step()
            assert np.allclose(net.output("K.STATE"), x, rtol=1e-5, atol=1e-6)
            assert np.allclose(net.output("K.INNOVATION"), y, rtol=1e-5, atol=1e-6)
            assert np.allclose(net.output("K.KALMAN_GAIN"), K, rtol=1e-5, atol=1e-6)
            assert net.output("K.NORMALIZED_INNOVATION")[0] == pytest.approx(nis, rel=1e-5)
            gates.append(float(net.output("K.GATED")[0]))
        assert gates == [g for *_, g, _ in expected] and 1.0 in gates
    finally:
        net.close()


def test_v3_default_matrices_keep_the_state_at_zero(tmp_path):
    # MODULES-V3 §25: a zero A or H acts as zero in every tick; y = z, S = R = 1, y'S⁻¹y = 4
    data_file(tmp_path, [("Z", 1)], [[2], [2]])
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>',
               dialect="3")
    try:
        net.step()
        assert net.output("K.STATE")[0] == 0 and net.output("K.KALMAN_GAIN")[0, 0] == 0
        assert net.output("K.NORMALIZED_INNOVATION")[0] == 4
    finally:
        net.close()


def test_empty_a_and_h_are_zero_as_in_the_original(tmp_path):
    # Ikaros 2 and 3 use all-zero matrices: the state stays 0 and the gain is 0
    data_file(tmp_path, [("Z", 1)], [[3], [3]])
    net = load(tmp_path, '<module class="InputFile" name="D" filename="d.txt"/>\n'
                         '<module class="KalmanFilter" name="K"/>\n'
                         '<connection source="D.Z" target="K.OBSERVATION" delay="0"/>')
    try:
        for _ in range(2):
            net.step()
            assert net.output("K.STATE")[0] == 0 and net.output("K.KALMAN_GAIN")[0, 0] == 0
            assert net.output("K.INNOVATION")[0] == 3
    finally:
        net.close()
