"""The Ikaros 3 KalmanFilter's tick (MODULES-V3 §25): matrices from parameters, an innovation
gate, the Joseph-form covariance update, and RESET to INITIAL_STATE / INITIAL_P."""
import numpy as np


def _active(x) -> bool:
    """An optional validity input is active when unconnected or when any element is not 0."""
    return x is None or bool(np.any(x != 0))


class Kalman3:
    """The filter's state (x, P) and its per-tick computation over the module's arrays."""

    def __init__(self, module):
        self.m = module
        n = module.state_size
        self.n, self.k = n, module.OBSERVATION.size
        self.u = module.INPUT.size if module.INPUT is not None else module.input_size
        self.initial_state = self.matrix("INITIAL_STATE", (n,))
        initial_p = self.matrix("INITIAL_P", (n, n))
        P = self.matrix("P", (n, n))
        if not P.any():
            P = initial_p.copy() if initial_p.any() else np.eye(n)
        self.initial_p = initial_p if initial_p.any() else P.copy()
        self.P = P
        self.x = np.zeros(n)
        self.matrices()             # checks the shapes now, so a bad model fails at load

    def matrix(self, name: str, shape: tuple) -> np.ndarray:
        """A matrix parameter: the scalar 0 (the default) is a zero matrix of ``shape``;
        another value must have ``shape`` (or its number of elements, read row by row)."""
        value = np.asarray(getattr(self.m, name), dtype=np.float64)
        if value.size <= 1 and not value.any():
            return np.zeros(shape)
        if value.shape == shape:
            return value
        if value.size == int(np.prod(shape)):
            return value.reshape(shape)
        raise ValueError(f"{name} has shape {value.shape}; it must be "
                         f"{' × '.join(str(s) for s in shape)}")

    def matrices(self):
        n, k, m = self.n, self.k, self.module_rates()
        A, H = self.matrix("A", (n, n)), self.matrix("H", (k, n))
        if self.m.default_matrices == "identity":
            A = A if A.any() else np.eye(n)
            H = H if H.any() else np.eye(k, n)
        B = self.matrix("B", (n, self.u)) if self.u else None
        Q, R = self.matrix("Q", (n, n)), self.matrix("R", (k, k))
        if not Q.any():
            Q = m[0] * np.eye(n)
        if not R.any():
            R = m[1] * np.eye(k)
        return A, B, H, Q, R

    def module_rates(self):
        m = self.m
        return m.process_noise * m.clock.tick_duration, m.observation_noise

    def outputs(self, innovation=0.0, gain=0.0, gated=0.0, normalized=0.0) -> None:
        m = self.m
        m.STATE[...] = self.x.reshape(m.STATE.shape)
        m.INNOVATION[...] = np.reshape(innovation, -1) if np.ndim(innovation) else innovation
        m.KALMAN_GAIN[...] = gain
        m.GATED[0] = gated
        m.NORMALIZED_INNOVATION[0] = normalized

    def tick(self) -> None:
        m = self.m
        if m.RESET is not None and np.any(m.RESET != 0):
            self.x, self.P = self.initial_state.copy(), self.initial_p.copy()
            self.outputs()
            return
        A, B, H, Q, R = self.matrices()
        x = A @ self.x
        if B is not None and m.INPUT is not None and _active(m.INPUT_VALID):
            x = x + B @ m.INPUT.reshape(-1).astype(np.float64)
        P = A @ self.P @ A.T + Q
        if not _active(m.OBSERVATION_VALID):
            self.x, self.P = x, P
            self.outputs()
            return
        y = m.OBSERVATION.reshape(-1).astype(np.float64) - H @ x
        S = H @ P @ H.T + R
        S_inv = self.inverse(S)
        if S_inv is None:               # the prediction is discarded; y is still shown
            m.INNOVATION[...] = y.reshape(m.INNOVATION.shape)
            return
        normalized = float(y @ S_inv @ y)
        if 0 < m.innovation_gate < normalized:
            self.x, self.P = x, P
            self.outputs(y, 0.0, 1.0, normalized)
            return
        K = P @ H.T @ S_inv
        self.x = x + K @ y
        I_KH = np.eye(self.n) - K @ H
        P = I_KH @ P @ I_KH.T + K @ R @ K.T
        self.P = 0.5 * (P + P.T)
        self.outputs(y, K, 0.0, normalized)

    def inverse(self, S):
        """S⁻¹, retried with inversion_jitter on the diagonal; None (and a warning) when it
        cannot be inverted."""
        tries = [S]
        if self.m.inversion_jitter > 0:
            tries.append(S + self.m.inversion_jitter * np.eye(len(S)))
        for s in tries:
            try:
                inv = np.linalg.inv(s)
            except np.linalg.LinAlgError:
                continue
            if np.all(np.isfinite(inv)):
                return inv
        self.m.warning("the innovation covariance S cannot be inverted; the tick keeps the "
                       "previous state")
        return None
