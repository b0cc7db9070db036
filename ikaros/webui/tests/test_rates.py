"""ticks/s over the last second and the run's mean, paused time left out (issue 16,
defect 1)."""
from ikaros.webui.rates import TickRate


def test_rate_over_the_last_second_and_mean_without_pauses():
    r = TickRate()
    assert r.sample(0, False, now=0.0) == {"ticks_per_second": None,
                                            "ticks_per_second_mean": None,
                                            "actual_tick_duration_mean": None}
    r.sample(0, True, now=1.0)                          # play
    for k in range(1, 11):                              # 100 ticks/s for 2 s
        out = r.sample(20 * k, True, now=1.0 + 0.2 * k)
    assert out["ticks_per_second"] == 100.0 and out["ticks_per_second_mean"] == 100.0
    assert out["actual_tick_duration_mean"] == 0.01     # issue 27, item 4: 1 / 100 ticks/s
    assert r.sample(200, False, now=3.1)["ticks_per_second"] is None        # paused
    r.sample(200, False, now=13.0)                      # 10 s paused
    r.sample(200, True, now=13.0)                       # play again, now 400 ticks/s
    out = r.sample(280, True, now=13.2)
    assert abs(out["ticks_per_second"] - 400) < 1e-9     # the window starts at the resume
    for k in range(2, 11):
        out = r.sample(200 + 80 * k, True, now=13.0 + 0.2 * k)
    assert abs(out["ticks_per_second"] - 400) < 1e-9
    # 200 ticks in 2.1 s (a pause seen 0.1 s late counts up to then) and 800 in 2 s;
    # the rest of the pause is not run time
    assert abs(out["ticks_per_second_mean"] - 1000 / 4.1) < 1e-9


def test_first_moments_use_the_tick_duration_and_a_new_network_resets():
    r = TickRate()
    r.sample(0, False, now=0.0)
    assert r.sample(3, True, now=0.01, tick_duration=0.002)["ticks_per_second"] == 500.0
    r.sample(500, True, now=1.0)
    out = r.sample(2, True, now=1.2)                    # ticks went back: a new network
    assert out["ticks_per_second"] is None and out["ticks_per_second_mean"] is None
