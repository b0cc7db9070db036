"""BalkeniusReactiveControl: a two-sensor, two-motor reactive controller (Balkenius 1995)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


def _positive(x):
    return max(0.0, x)


class BalkeniusReactiveControl(Module):
    """The reactive controller of Balkenius (1995, Fig. 4.10), as in Ikaros 3. The sensor
    values s_L, s_R are column ``odour_channel`` (rounded, clamped into the columns) of rows
    0 and 1 of ODOUR when it is connected, else SENSORS[0] and SENSORS[1], else 0. With
    ⁺ = max(0, ·): the interneurons are a_L = (s_L − θ)⁺, a_R = (s_R − θ)⁺ and
    c = ((s_L + s_R)/2 − θ)⁺; with ``weights`` m, n, o, p, q, r (missing entries 0) the
    motor activities are L = r + m·s_R + o·s_L − n·a_L − q·a_R − p·c and R = r + m·s_L +
    o·s_R − n·a_R − q·a_L − p·c, then (· − motor_threshold)⁺ (RAW_MOTOR), then gain times
    that clipped to ±max(0, max_motor) (MOTOR). SENSORY is (s_L, s_R) and NODES (a_L, c,
    a_R). ``behavior``, ``a``, ``b`` and ``c`` are unused, as in Ikaros 3 (whose presets
    are disabled). New in Ikaros 3."""

    behavior = Parameter("0", "unused (Ikaros 3's presets are disabled)", type="matrix")
    weights = Parameter("0, 0, 0, 0, 0, 0", "the weights m, n, o, p, q, r", type="array")
    a = Parameter(0.20, "unused, as in Ikaros 3")
    b = Parameter(0.08, "unused, as in Ikaros 3")
    c = Parameter(0.04, "unused, as in Ikaros 3")
    theta = Parameter(0.05, "the threshold θ of the interneurons")
    motor_threshold = Parameter(0.0, "subtracted from the motor activities before "
                                "rectification")
    gain = Parameter(1.0, "multiplies the rectified motor activities")
    max_motor = Parameter(0.25, "the largest motor output (in either direction)")
    odour_channel = Parameter(0.0, "the column of ODOUR that is read")
    SENSORS = Input("left and right sensor values", optional=True, flatten=True)
    ODOUR = Input("odour intensities: rows left, right; one column per odour channel",
                  optional=True)
    MOTOR = Output("left and right motor commands", size="2")
    SENSORY = Output("the sensor values used, s_L and s_R", size="2")
    RAW_MOTOR = Output("the rectified motor activities before gain and clipping", size="2")
    NODES = Output("the interneurons a_L, c, a_R", size="3")

    def init(self):
        if self.ODOUR is not None and (self.ODOUR.ndim < 2 or self.ODOUR.shape[0] < 2):
            self.fatal_error(f"ODOUR needs at least 2 rows (left, right), not shape "
                             f"{self.ODOUR.shape}")
        elif self.ODOUR is None and self.SENSORS is not None and self.SENSORS.size < 2:
            self.fatal_error(f"SENSORS needs 2 elements, not {self.SENSORS.size}")

    def _sensors(self):
        if self.ODOUR is not None:
            rows = self.ODOUR.reshape(self.ODOUR.shape[0], -1)
            column = int(np.clip(np.round(self.odour_channel), 0, rows.shape[1] - 1))
            return float(rows[0, column]), float(rows[1, column])
        if self.SENSORS is not None:
            return float(self.SENSORS[0]), float(self.SENSORS[1])
        return 0.0, 0.0

    def tick(self):
        s_l, s_r = self._sensors()
        m, n, o, p, q, r = (list(np.ravel(self.weights).astype(float)) + [0.0] * 6)[:6]
        theta = self.theta
        a_l, a_r = _positive(s_l - theta), _positive(s_r - theta)
        c = _positive((s_l + s_r) / 2 - theta)
        left = r + m * s_r + o * s_l - n * a_l - q * a_r - p * c
        right = r + m * s_l + o * s_r - n * a_r - q * a_l - p * c
        raw = [_positive(left - self.motor_threshold), _positive(right - self.motor_threshold)]
        limit = max(0.0, self.max_motor)
        self.RAW_MOTOR[...] = raw
        self.MOTOR[...] = np.clip(self.gain * np.array(raw), -limit, limit)
        self.SENSORY[...] = (s_l, s_r)
        self.NODES[...] = (a_l, c, a_r)
