"""Tests of the PIDController module."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body as load


def reference(inputs, setpoints, Kb=0.0, Kp=0.1, Ki=0.0, Kd=0.0, Fs=0.0, Fm=0.0, Fp=0.0,
              Fi=0.0, Fd=0.0, Fc=0.0, Cmin=-1000.0, Cmax=1000.0):
    """The documented PID computation, one tick at a time, in float64."""
    n = max(np.size(inputs[0]), np.size(setpoints[0]))
    fs = fm = ep = ei = ed = integral = out = last_d = np.zeros(n)
    rows = []
    for x, s in zip(inputs, setpoints):
        fs = Fs * fs + (1 - Fs) * np.asarray(s, float)
        fm = Fm * fm + (1 - Fm) * np.asarray(x, float)
        delta = fs - fm
        ep = Fp * ep + (1 - Fp) * delta
        ei = Fi * ei + (1 - Fi) * delta
        ed = Fd * ed + (1 - Fd) * delta
        integral = integral + ei
        c = Kb + Kp * ep + Ki * integral + Kd * (ed - last_d)
        last_d = ed
        clipped = (c > Cmax) | (c < Cmin)
        integral = np.where(clipped, integral - ei, integral)
        c = np.clip(c, Cmin, Cmax)
        out = Fc * out + (1 - Fc) * c
        rows.append(dict(OUTPUT=out, DELTA=delta, FILTERED_SETPOINT=fs, FILTERED_INPUT=fm,
                         FILTERED_ERROR_P=ep, FILTERED_ERROR_I=ei, FILTERED_ERROR_D=ed,
                         INTEGRAL=integral))
    return rows


def body(params, setpoint="1 -2", data="0 0; 0.5 -1; 1 -1.5; 2 0; 1.5 -3; 0 0; 1 1; -1 2"):
    return (f'<module class="Constant" name="S" data="{setpoint}"/>\n'
            f'<module class="InputFile" name="X" filename="x.txt"/>\n'
            f'<module class="PIDController" name="P" {params}/>\n'
            '<connection source="S.OUTPUT" target="P.SETPOINT" delay="0"/>\n'
            '<connection source="X.X" target="P.INPUT" delay="0"/>\n')


def write_inputs(tmp_path, rows):
    cols = len(rows[0])
    text = f"X/{cols}\n" + "\n".join(" ".join(str(v) for v in r) for r in rows) + "\n"
    (tmp_path / "x.txt").write_text(text)


ROWS = [[0, 0], [0.5, -1], [1, -1.5], [2, 0], [1.5, -3], [0, 0], [1, 1], [-1, 2]]


def run_and_compare(tmp_path, params, setpoint=(1, -2), rows=ROWS):
    write_inputs(tmp_path, rows)
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items()) + ' derivative_mode="error"'
    net = load(tmp_path, body(attrs, " ".join(map(str, setpoint))))
    try:
        expected = reference(rows, [setpoint] * len(rows), **params)
        for tick, want in enumerate(expected):
            net.step()
            for name, value in want.items():
                assert np.allclose(net.output(f"P.{name}"), value, atol=1e-5), (tick, name)
    finally:
        net.close()


def test_default_is_proportional_with_gain_0_1(tmp_path):
    write_inputs(tmp_path, ROWS)
    net = load(tmp_path, body(""))
    try:
        assert net.output("P.OUTPUT").shape == (2,)
        net.step()
        assert np.allclose(net.output("P.OUTPUT"), [0.1, -0.2])       # 0.1 * (s - x)
        net.step()
        assert np.allclose(net.output("P.OUTPUT"), [0.05, -0.1])
        assert np.allclose(net.output("P.DELTA"), [0.5, -1])
    finally:
        net.close()


def test_full_pid_against_reference(tmp_path):
    run_and_compare(tmp_path, dict(Kb=0.2, Kp=0.5, Ki=0.1, Kd=0.3))


def test_filters_against_reference(tmp_path):
    run_and_compare(tmp_path, dict(Kp=0.7, Ki=0.2, Kd=0.4, Fs=0.5, Fm=0.25, Fp=0.1,
                                   Fi=0.3, Fd=0.6, Fc=0.2))


def test_clipping_stops_integration(tmp_path):
    # error [1, -2] for four ticks: the integral saturates the output and stops growing;
    # then the error flips to [-1, 1] and the output leaves saturation at once
    rows = [[0, 0]] * 4 + [[2, -3]] * 2
    run_and_compare(tmp_path, dict(Kp=0.0, Ki=1.0, Cmin=-3, Cmax=2.5), rows=rows)
    net = load(tmp_path, body('Kp="0" Ki="1" Cmin="-3" Cmax="2.5"'))
    try:
        got = []
        for _ in range(6):
            net.step()
            got.append((net.output("P.OUTPUT").tolist(), net.output("P.INTEGRAL").tolist()))
        assert got == [([1, -2], [1, -2]), ([2, -3], [2, -2]), ([2.5, -3], [2, -2]),
                       ([2.5, -3], [2, -2]), ([1, -1], [1, -1]), ([0, 0], [0, 0])]
    finally:
        net.close()


def test_derivative_memory_starts_at_0(tmp_path):
    # as in Ikaros 2: on the first tick the change is the signal itself (error [1, -2])
    rows = [[0, 0], [0.5, 0], [0.5, 0]]
    write_inputs(tmp_path, rows)
    net = load(tmp_path, body('Kp="0" Kd="2" derivative_mode="error"'))
    try:
        net.step()
        assert np.allclose(net.output("P.OUTPUT"), [2, -4])
        net.step()                    # error falls from 1 to 0.5: derivative -0.5, times 2
        assert np.allclose(net.output("P.OUTPUT"), [-1, 0])
        net.step()
        assert np.allclose(net.output("P.OUTPUT"), [0, 0])
    finally:
        net.close()


def test_one_setpoint_serves_every_element(tmp_path):
    write_inputs(tmp_path, ROWS)
    net = load(tmp_path, body('Kp="1"', setpoint="0.5"))
    try:
        for row in ROWS:
            net.step()
            assert np.allclose(net.output("P.OUTPUT"), 0.5 - np.array(row))
    finally:
        net.close()


def test_mismatched_sizes_are_a_build_error(tmp_path):
    write_inputs(tmp_path, ROWS)
    with pytest.raises(ModelError, match="INPUT has 2 elements and SETPOINT 3"):
        load(tmp_path, body("", setpoint="1 2 3"))


# --- the optional inputs: GATED, INPUT_VALID, RESET -------------------------------------------
# Setpoint 1 and measurement 0 in both elements, Kp=0.5, Ki=0.25: the error is 1 every tick,
# so an element's output after its k-th counted tick is 0.5 + 0.25 * k.

def run_v3(tmp_path, columns, params=""):
    """Runs the controller with the given Ikaros 3 inputs read from a file, one row per tick
    ({input name: (rows of values)}); returns OUTPUT and INTEGRAL after each tick."""
    names = list(columns)
    rows = zip(*(columns[n] for n in names))
    header = " ".join(f"{n}/{len(columns[n][0])}" for n in names)
    (tmp_path / "v3.txt").write_text(
        header + "\n" + "\n".join(" ".join(str(v) for group in r for v in group)
                                  for r in rows) + "\n")
    body = ('<module class="Constant" name="S" data="1 1"/>\n'
            '<module class="Constant" name="X" data="0 0"/>\n'
            '<module class="InputFile" name="F" filename="v3.txt"/>\n'
            f'<module class="PIDController" name="P" Kp="0.5" Ki="0.25" {params}/>\n'
            '<connection source="S.OUTPUT" target="P.SETPOINT" delay="0"/>\n'
            '<connection source="X.OUTPUT" target="P.INPUT" delay="0"/>\n' +
            "".join(f'<connection source="F.{n}" target="P.{n}" delay="0"/>\n' for n in names))
    net = load(tmp_path, body)
    out = []
    try:
        for _ in range(len(columns[names[0]])):
            net.step()
            out.append((net.output("P.OUTPUT").tolist(), net.output("P.INTEGRAL").tolist()))
    finally:
        net.close()
    return out


def test_reset_clears_the_integral_with_use_reset(tmp_path):
    out = run_v3(tmp_path, {"RESET": [[0], [0], [1], [0]]}, 'use_reset="yes"')
    assert out == [([0.75, 0.75], [1, 1]), ([1.0, 1.0], [2, 2]),
                   ([0.75, 0.75], [1, 1]), ([1.0, 1.0], [2, 2])]


def test_ikaros_2_file_ignores_reset(tmp_path):
    # Ikaros 2 ignores RESET: the integral keeps adding up (golden-v2 PIDController)
    out = run_v3(tmp_path, {"RESET": [[0], [1], [1], [0]]})
    assert out == [([0.75, 0.75], [1, 1]), ([1.0, 1.0], [2, 2]),
                   ([1.25, 1.25], [3, 3]), ([1.5, 1.5], [4, 4])]


def test_input_valid_holds_an_element(tmp_path):
    out = run_v3(tmp_path, {"INPUT_VALID": [[1, 1], [1, 0], [1, 0], [1, 1]]})
    assert out == [([0.75, 0.75], [1, 1]), ([1.0, 0.75], [2, 1]),
                   ([1.25, 0.75], [3, 1]), ([1.5, 1.0], [4, 2])]


def test_gated_switches_an_element_off(tmp_path):
    out = run_v3(tmp_path, {"GATED": [[1, 0], [1, 0], [1, 1], [0, 1]]})
    assert out == [([0.75, 0.0], [1, 0]), ([1.0, 0.0], [2, 0]),
                   ([1.25, 0.75], [3, 1]), ([0.0, 1.0], [0, 2])]


def test_optional_input_of_wrong_size_is_an_error(tmp_path):
    with pytest.raises(ModelError, match="GATED has 3 elements"):
        run_v3(tmp_path, {"GATED": [[1, 1, 1]]})



def reference_v3(inputs, setpoint, dt, Kb=0.0, Kp=0.1, Ki=0.0, Kd=0.0, Fs=0.0, Fm=0.0,
                 Fp=0.0, Fi=0.0, Fd=0.0, Fc=0.0, limit=0.0, mode="measurement",
                 Cmin=-1000.0, Cmax=1000.0):
    """The Ikaros 3 controller of one element, written from docs of the class (rate filters,
    integral and derivative per second, rate-limited output)."""
    def w(rate):
        return 1.0 if rate == 0 else 1 - np.exp(-rate * dt)
    fs = fm = p = i = d = integral = out = previous = 0.0
    outputs = []
    for x in inputs:
        fs += w(Fs) * (setpoint - fs)
        fm += w(Fm) * (x - fm)
        delta = fs - fm
        p += w(Fp) * (delta - p)
        i += w(Fi) * (delta - i)
        signal = delta if mode == "error" else -fm
        d += w(Fd) * ((signal - previous) / dt - d)
        previous = signal
        integral += i * dt
        c = Kb + Kp * p + Ki * integral + Kd * d
        if not Cmin <= c <= Cmax:
            integral -= i * dt
            c = min(max(c, Cmin), Cmax)
        new = out + w(Fc) * (c - out)
        out = new if limit == 0 else min(max(new, out - limit * dt), out + limit * dt)
        outputs.append(out)
    return outputs


def test_ikaros_3_rates_error_derivative_and_rate_limit(tmp_path):
    inputs = [0.0, 0.5, 1.0, 1.2, 1.1, 0.9, 1.0, 1.0]
    (tmp_path / "x.txt").write_text("X/1\n" + "".join(f"{v}\n" for v in inputs))
    gains = dict(Kp=1.2, Ki=0.8, Kd=0.1, Fs=2, Fm=5, Fp=3, Fi=1, Fd=4, Fc=6, Cmax=1.5)
    text = " ".join(f'{k}="{v}"' for k, v in gains.items())
    net = load(tmp_path, '<module class="InputFile" name="F" filename="x.txt"/>'
                         '<module class="Constant" name="S" data="1"/>'
                         f'<module class="PIDController" name="P" {text} '
                         'output_rate_limit="4" derivative_mode="error"/>'
                         '<connection source="F.X" target="P.INPUT" delay="0"/>'
                         '<connection source="S.OUTPUT" target="P.SETPOINT" delay="0"/>',
               dialect="3", tick_duration="0.05")
    try:
        got = []
        for _ in inputs:
            net.step()
            got.append(float(net.output("P.OUTPUT")[0]))
    finally:
        net.close()
    expected = reference_v3(inputs, 1.0, 0.05, limit=4, mode="error", **gains)
    np.testing.assert_allclose(got, expected, rtol=1e-5, atol=1e-6)


@pytest.mark.parametrize("mode, sign", [("input", 1), ("measurement", -1)])
def test_ikaros_2_derivative_of_the_filtered_input(tmp_path, mode, sign):
    # the default (input) is Ikaros 2's: Kd times the change of the filtered input, which
    # pushes the output the wrong way; measurement corrects the sign. Fd is not used.
    rows = [[0, 0], [0.5, 0], [1.5, -1], [1.5, -1]]
    write_inputs(tmp_path, rows)
    attrs = 'Kp="0" Kd="2" Fm="0.5" Fd="0.9"' + ("" if mode == "input" else
                                                  f' derivative_mode="{mode}"')
    net = load(tmp_path, body(attrs, data=""))
    try:
        fm, last, got, expected = np.zeros(2), np.zeros(2), [], []
        for row in rows:
            fm = 0.5 * fm + 0.5 * np.array(row)
            expected.append(sign * 2 * (fm - last))
            last = fm.copy()
            net.step()
            got.append(net.output("P.OUTPUT").copy())
        assert np.allclose(got, expected, atol=1e-6)
    finally:
        net.close()
