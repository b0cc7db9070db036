"""KalmanFilter: a linear Kalman filter."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._kalman3 import Kalman3


class KalmanFilter(Module):
    """A standard linear Kalman filter for the process x(t+1) = A·x(t) + B·u(t) observed as z =
    H·x. Every tick it predicts x' = A·x + B·u (u is INPUT; no term when INPUT is not connected)
    and P' = A·P·Aᵀ + Q, then corrects with the OBSERVATION z: INNOVATION y = z − H·x', S =
    H·P'·Hᵀ + R, KALMAN_GAIN K = P'·Hᵀ·S⁻¹, STATE x = x' + K·y and P = (I − K·H)·P'. Q is
    ``process_noise`` times the identity and R is ``observation_noise`` times the identity; the
    state starts at 0 with P = I. A is ``state_size`` × ``state_size``, B is ``state_size`` ×
    (elements of INPUT) and H is ``observation_size`` × ``state_size``; a matrix given as one
    row of the right number of elements is read row by row. The golden files show Ikaros 2
    computing these formulas with A, B and H given. An empty B is zero, and so are an empty A
    and H, which keeps the state at 0: that is Ikaros 3's behaviour, and for Ikaros 2 this
    project's reading (no reference shows an Ikaros 2 filter without them);
    ``default_matrices="identity"`` (this project's) makes an empty A the identity and an empty
    H ones on its diagonal. OBSERVATION must have ``observation_size`` elements (another size
    is refused here; no reference shows what Ikaros 2 does with it). If S cannot be inverted
    the correction is skipped for that tick and a warning is given once.

    The ports and parameters of today's Ikaros 3 class are accepted in an Ikaros 2 file too,
    where they are this project's additions to the Ikaros 2 filter (the Ikaros 2 class has
    none of them); left unconnected and at their defaults, the filter works as above.
    NORMALIZED_INNOVATION is yᵀS⁻¹y of the observation used; with ``innovation_gate`` above
    0 an observation whose normalized innovation exceeds it is rejected (the tick is a
    prediction only, KALMAN_GAIN 0) and GATED is 1, else 0. RESET: on a tick when its first
    element is above 0, the state restarts (x = 0, P = I) before that tick. INPUT_VALID: on
    a tick when its first element is 0 or below, the control input is left out of the
    prediction. OBSERVATION_VALID (one element for all, or observation_size elements): only
    the observation elements above 0 correct the state; the others have INNOVATION 0 and a
    KALMAN_GAIN column of 0, and with none valid the tick is a prediction only. ENABLE (this
    project's, in both dialects): on a tick when its first element is 0 or below, the
    filter does nothing (state and outputs are held). In an Ikaros 2 file of this project
    written before GATED became an output, that input was called GATED.

    In an Ikaros 3 file (dialect 3) the class is Ikaros 3's: k = OBSERVATION's size
    (observation_size is not used), GATED is an output (1 when ``innovation_gate`` > 0 and
    the normalized innovation yᵀS⁻¹y, output as NORMALIZED_INNOVATION, exceeds it: the
    observation is rejected and the tick is a prediction), INPUT_VALID and
    OBSERVATION_VALID act on the whole vector (inactive when connected and all 0), and
    RESET (any element not 0) sets STATE to INITIAL_STATE and P to INITIAL_P for the tick.
    A matrix parameter left at 0 is a zero matrix every tick (so the defaults keep the
    state at 0, as in Ikaros 3); Q and R left at 0 are process_noise·tick_duration·I and
    observation_noise·I; P starts at the ``P`` parameter, else INITIAL_P, else I. The
    covariance update is the Joseph form, symmetrized. If S cannot be inverted (after a
    retry with ``inversion_jitter`` on its diagonal when that is > 0) the tick keeps the
    previous state. Ikaros 3 rejects a matrix of the wrong shape; here one with the right
    number of elements is read row by row (so ``A="1"`` is the 1 × 1 matrix 1)."""

    A = Parameter(None, "the state transition matrix, state_size × state_size; empty: zero "
                  "(see default_matrices)", type="matrix")
    B = Parameter(None, "the control input matrix, state_size × (elements of INPUT); empty: "
                  "zero", type="matrix")
    H = Parameter(None, "the observation matrix, observation_size × state_size; empty: zero "
                  "(see default_matrices)", type="matrix")
    default_matrices = Parameter("zero", "what an empty (or, in an Ikaros 3 file, 0) A and H "
                                 "are: zero (the original) or identity",
                                 options="zero/identity")
    state_size = Parameter(1, "number of elements of the state", type="int", range=(1, None))
    observation_size = Parameter(1, "number of elements of the observation", type="int",
                                 range=(1, None))
    process_noise = Parameter(1.0, "the variance of the process noise (Q = process_noise·I; "
                              "Ikaros 3: per second, times tick_duration)")
    observation_noise = Parameter(1.0, "the variance of the observation noise "
                                  "(R = observation_noise·I)")
    input_size = Parameter(1, "Ikaros 3: the columns of B when INPUT is not connected",
                           type="int", range=(0, None))
    innovation_gate = Parameter(0.0, "the largest normalized innovation yᵀS⁻¹y "
                                "accepted (0: no gate)")
    inversion_jitter = Parameter(0.0, "Ikaros 3: added to S's diagonal on a retry when S "
                                 "cannot be inverted")
    Q = Parameter(None, "Ikaros 3: the process noise covariance, state_size × state_size; "
                  "0: process_noise·tick_duration·I", type="matrix")
    R = Parameter(None, "Ikaros 3: the observation noise covariance, k × k; 0: "
                  "observation_noise·I", type="matrix")
    INITIAL_STATE = Parameter(None, "Ikaros 3: the state after RESET", type="matrix")
    INITIAL_P = Parameter(None, "Ikaros 3: the covariance after RESET (0: the starting P)",
                          type="matrix")
    P = Parameter(None, "Ikaros 3: the starting covariance (0: INITIAL_P, or I)",
                  type="matrix")

    INPUT = Input("the control input u", optional=True)
    OBSERVATION = Input("the observation z, of observation_size elements")
    INPUT_VALID = Input("a first element of 0 or below leaves INPUT out (Ikaros 3: all "
                        "elements 0)", optional=True)
    OBSERVATION_VALID = Input("which observation elements are used: above 0 (Ikaros 3: the "
                              "whole observation unless all elements are 0)", optional=True)
    RESET = Input("a first element above 0 restarts the state (Ikaros 3: any element not 0, "
                  "to INITIAL_STATE and INITIAL_P)", optional=True)
    ENABLE = Input("this project's: a first element of 0 or below holds the filter for the "
                   "tick", optional=True)

    STATE = Output("the state estimate x", size_param="state_size")
    INNOVATION = Output("the observation minus the predicted observation, z − H·x'",
                        size_set="OBSERVATION")
    KALMAN_GAIN = Output("the Kalman gain K, state_size × observation_size (Ikaros 3: "
                         "state_size × OBSERVATION's size)")
    GATED = Output("1 when the innovation gate rejected the observation, else 0", size="1")
    NORMALIZED_INNOVATION = Output("yᵀS⁻¹y, the squared innovation scaled by its covariance",
                                   size="1")

    def set_sizes(self):
        k = self.observation_size
        if self.dialect == "3":
            shape = self.input_shape("OBSERVATION")
            if shape is None:
                return
            k = int(np.prod(shape))
        self.set_output_shape("KALMAN_GAIN", (self.state_size, k))

    def init(self):
        if self.dialect == "3":
            self._v3 = Kalman3(self)
            self.STATE.fill(0)
            return
        self._v3 = None
        n, m = self.state_size, self.observation_size
        if n < 1 or m < 1:
            raise ValueError("state_size and observation_size must be at least 1")
        if self.OBSERVATION.size != m:
            raise ValueError(f"OBSERVATION has {self.OBSERVATION.size} elements but "
                             f"observation_size is {m}")
        self._u = 0 if self.INPUT is None else self.INPUT.size
        self._matrices()            # checks the shapes now, so a bad model fails at load
        if self.INPUT is not None and self.B.size == 0:
            self.warning("INPUT is connected but B is empty, so the input has no effect")
        valid = self.OBSERVATION_VALID
        if valid is not None and valid.size not in (1, m):
            raise ValueError(f"OBSERVATION_VALID has {valid.size} elements: it must have 1 "
                             f"or observation_size ({m})")
        self._x = np.zeros(n)
        self._P = np.eye(n)
        self._warned = False
        self.STATE.fill(0)
        self.INNOVATION.fill(0)
        self.KALMAN_GAIN.fill(0)
        self.GATED.fill(0)
        self.NORMALIZED_INNOVATION.fill(0)

    def _matrix(self, name, rows, cols, empty):
        value = np.asarray(getattr(self, name), dtype=np.float64)
        if value.size == 0:
            return empty
        if value.shape == (rows, cols):
            return value
        if value.size == rows * cols and (value.ndim == 1 or value.shape[0] == 1):
            return value.reshape(rows, cols)
        raise ValueError(f"{name} has shape {value.shape}; it must be {rows} × {cols}")

    def _matrices(self):
        n, m, u = self.state_size, self.observation_size, self._u
        identity = self.default_matrices == "identity"
        return (self._matrix("A", n, n, np.eye(n) if identity else np.zeros((n, n))),
                self._matrix("B", n, u, np.zeros((n, u))) if u else None,
                self._matrix("H", m, n, np.eye(m, n) if identity else np.zeros((m, n))))

    @staticmethod
    def _on(x) -> bool:
        """Whether a gate-like input's first element is above 0."""
        return bool(x.size and x.flat[0] > 0)

    def tick(self):
        if self.ENABLE is not None and not self._on(self.ENABLE):
            return
        if self._v3 is not None:
            self._v3.tick()
            return
        if self.RESET is not None and self._on(self.RESET):
            self._x = np.zeros(self.state_size)
            self._P = np.eye(self.state_size)
        n, m = self.state_size, self.observation_size
        A, B, H = self._matrices()
        Q = self.process_noise * np.eye(n)

        x = A @ self._x
        if B is not None and (self.INPUT_VALID is None or self._on(self.INPUT_VALID)):
            x += B @ self.INPUT.reshape(-1).astype(np.float64)
        P = A @ self._P @ A.T + Q
        used = np.ones(m, dtype=bool) if self.OBSERVATION_VALID is None else \
            np.broadcast_to(self.OBSERVATION_VALID.reshape(-1) > 0, (m,))
        y = np.where(used, self.OBSERVATION.reshape(-1).astype(np.float64) - H @ x, 0.0)
        K = np.zeros((n, m))
        gated = normalized = 0.0
        if used.any():
            Hu = H[used]
            S = Hu @ P @ Hu.T + self.observation_noise * np.eye(int(used.sum()))
            try:
                # K = P Hᵀ S⁻¹, computed as the solution of Sᵀ Kᵀ = H Pᵀ
                Ku = np.linalg.solve(S.T, Hu @ P.T).T
                normalized = float(y[used] @ np.linalg.solve(S, y[used]))
                if not np.all(np.isfinite(Ku)):
                    raise np.linalg.LinAlgError("non-finite gain")
            except np.linalg.LinAlgError:
                if not self._warned:
                    self.warning("the innovation covariance S is singular; the observation "
                                 "is not used on such ticks")
                    self._warned = True
            else:
                if 0 < self.innovation_gate < normalized:
                    gated = 1.0
                else:
                    K[:, used] = Ku
                    x = x + Ku @ y[used]
                    P = (np.eye(n) - Ku @ Hu) @ P
                    P = 0.5 * (P + P.T)
        self._x, self._P = x, P
        self.GATED[0] = gated
        self.NORMALIZED_INNOVATION[0] = normalized
        self.STATE[...] = x.reshape(self.STATE.shape)
        self.INNOVATION[...] = y.reshape(self.INNOVATION.shape)
        self.KALMAN_GAIN[...] = K.reshape(self.KALMAN_GAIN.shape)
