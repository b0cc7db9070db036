"""SCN against the equations of Forger, Jewett & Kronauer (1999) (parameters of Serkh &
Forger 2014) integrated here with SciPy's adaptive Runge-Kutta, tick by tick with the light
of each tick, and the oscillator's behaviour: it free-runs with its intrinsic period in the
dark and is entrained to a 24-hour light-dark cycle."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body

solve_ivp = pytest.importorskip("scipy.integrate").solve_ivp


def forger(t, s, lux, tau):
    x, xc, n = s
    alpha = 0.05 * (lux / 9500) ** 0.5
    b = 33.75 * (1 - n) * alpha * (1 - 0.4 * x) * (1 - 0.4 * xc)
    return [np.pi / 12 * (xc + b),
            np.pi / 12 * (0.23 * (xc - 4 * xc ** 3 / 3) - x * ((24 / (0.99669 * tau)) ** 2
                                                             + 0.55 * b)),
            60 * (alpha * (1 - n) - 0.0075 * n)]


def reference(light, hours_per_tick, tau, max_lux=10000.0):
    """x after each tick, and its change, for the light of each tick (0..1)."""
    state, xs = np.array([0.0, 1.0, 0.0]), []
    for value in light:
        solution = solve_ivp(forger, (0, hours_per_tick), state,
                             args=(max_lux * value, tau), rtol=1e-10, atol=1e-12)
        state = solution.y[:, -1]
        xs.append(state[0])
    xs = np.array(xs)
    return xs, np.diff(np.concatenate([[0.0], xs]))


def run_scn(tmp_path, light, tick_duration, **params):
    """Run the SCN on one light value a tick; return OUTPUT and DIFF of each tick."""
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    values = " ".join(repr(float(v)) for v in light)
    body = (f'<module class="ListIterator" name="L" listdata="{values}"/>'
            f'<module class="SCN" name="M" {attrs}/>'
            '<connection source="L.OUTPUT" target="M.INPUT" delay="0"/>')
    x, diff = [], []
    with load_body(tmp_path, body, tick_duration=str(tick_duration)) as net:
        for _ in range(len(light)):
            net.step()
            x.append(float(net.output("M.OUTPUT")[0]))
            diff.append(float(net.output("M.DIFF")[0]))
    return np.array(x), np.array(diff)


def light_dark(days, ticks_per_day, light_hours=12, level=1.0):
    hour = (np.arange(days * ticks_per_day) % ticks_per_day) * 24 / ticks_per_day
    return np.where(hour < light_hours, level, 0.0)


def test_follows_the_equations_tick_by_tick(tmp_path):
    light = light_dark(3, 48, level=0.3)                     # half-hour ticks
    x, diff = run_scn(tmp_path, light, 1800)
    expected_x, expected_diff = reference(light, 0.5, tau=25.0, max_lux=10000)
    assert np.allclose(x, expected_x, atol=2e-6)
    assert np.allclose(diff, expected_diff, atol=2e-6)


def test_frequency_and_max_lux_are_the_period_and_the_scale_of_the_light(tmp_path):
    light = light_dark(2, 24, level=0.5)                     # hour ticks, 20-hour period
    x, _ = run_scn(tmp_path, light, 3600, frequency=str(1 / (20 * 3600)), max_lux="500")
    expected_x, _ = reference(light, 1.0, tau=20.0, max_lux=500)
    assert np.allclose(x, expected_x, atol=2e-6)


def upward_crossings(x, hours_per_tick):
    """The times (hours) at which x rises through 0, by linear interpolation."""
    i = np.flatnonzero((x[:-1] < 0) & (x[1:] >= 0))
    return (i + x[i] / (x[i] - x[i + 1]) + 1) * hours_per_tick


@pytest.mark.slow
def test_free_runs_with_its_period_in_the_dark_and_is_entrained_by_a_day(tmp_path):
    ticks_per_day = 96                                        # quarter-hour ticks
    dark = np.zeros(30 * ticks_per_day)
    x, _ = run_scn(tmp_path, dark, 900)
    periods = np.diff(upward_crossings(x, 0.25))[-10:]
    assert np.allclose(periods, 25.0, atol=0.1)
    x, _ = run_scn(tmp_path, light_dark(30, ticks_per_day), 900)
    periods = np.diff(upward_crossings(x, 0.25))[-10:]
    assert np.allclose(periods, 24.0, atol=0.02)


def test_a_frequency_of_zero_is_refused(tmp_path):
    with pytest.raises(ModelError, match="frequency must be above 0"):
        run_scn(tmp_path, [0.0, 0.0], 60, frequency="0")
