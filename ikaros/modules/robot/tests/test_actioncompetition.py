"""ActionCompetition against a step-by-step reference of its documented rule."""
import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body


def reference(bias, ticks, duration, complete=None, initial_delay=0, rest=0.0, lo=0.0, hi=1.0,
              passive=0.1, threshold=0.0, completion_bias=1.0):
    n = len(bias)
    a = np.full(n, rest)
    running, remaining = -1, 0
    rows = []
    for t in range(ticks):
        a = np.clip(a + bias - passive * (a - rest), lo, hi)
        trigger = np.zeros(n)
        if running >= 0:
            remaining -= 1
            if remaining <= 0 or (complete is not None and complete(t)[running] > 0.5):
                a[running] = max(a[running] - completion_bias, lo)
                running = -1
        if running < 0 and t >= initial_delay:
            w = int(np.argmax(a))
            if a[w] > threshold:
                running, remaining = w, duration[w]
                trigger[w] = 1
        active = np.zeros(n)
        if running >= 0:
            active[running] = 1
        rows.append((a.copy(), trigger, active))
    return rows


def run(tmp_path, params, bias="0.3 0.2 0.1", ticks=40):
    body = (f'<module class="Constant" name="B" data="{bias}"/>\n'
            f'<module class="ActionCompetition" name="AC" size="3" {params}/>\n'
            '<connection source="B.OUTPUT" target="AC.INPUT" delay="0"/>')
    net = load_body(tmp_path, body)
    rows = []
    for _ in range(ticks):
        net.step()
        rows.append(tuple(net.output(f"AC.{o}") for o in ("OUTPUT", "TRIGGER", "ACTIVE")))
    net.close()
    return rows


@pytest.mark.parametrize("params, kwargs", [
    ('duration="5"', dict(duration=[5, 5, 5])),
    ('duration="3 8 4" initial_delay="4" passive="0.3" threshold="0.5"',
     dict(duration=[3, 8, 4], initial_delay=4, passive=0.3, threshold=0.5)),
    ('duration="6" rest="0.2" min="-1" max="2" completion_bias="3"',
     dict(duration=[6] * 3, rest=0.2, lo=-1, hi=2, completion_bias=3))])
def test_matches_the_documented_rule(tmp_path, params, kwargs):
    got = run(tmp_path, params)
    want = reference(np.array([0.3, 0.2, 0.1]), 40, **kwargs)
    for tick, (g, w) in enumerate(zip(got, want)):
        for k in range(3):
            assert np.allclose(g[k], w[k], atol=1e-5), (tick, k)


def test_actions_take_turns(tmp_path):
    rows = run(tmp_path, 'duration="5"')
    winners = [int(np.argmax(t)) for _, t, _ in rows if t.max() > 0]
    assert rows[0][1].tolist() == [1, 0, 0]                  # the most pushed wins at once
    assert winners[:3] == [0, 1, 0] and len(winners) >= 6     # completion hands over
    assert all(r[1].sum() <= 1 and r[2].sum() <= 1 for r in rows)


def test_complete_input_ends_an_action_early(tmp_path):
    body = ('<module class="Constant" name="B" data="0.3 0.2"/>\n'
            '<module class="Constant" name="C" data="1 0"/>\n'
            '<module class="ActionCompetition" name="AC" size="2" duration="100"/>\n'
            '<connection source="B.OUTPUT" target="AC.INPUT" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="AC.COMPLETE" delay="0"/>\n')
    net = load_body(tmp_path, body)
    try:
        net.step()
        assert net.output("AC.TRIGGER").tolist() == [1, 0]
        net.step()                                        # COMPLETE[0] ends action 0 at once
        assert net.output("AC.TRIGGER").tolist() == [0, 1]
        assert net.output("AC.ACTIVE").tolist() == [0, 1]
    finally:
        net.close()


def test_sizes_are_checked(tmp_path):
    with pytest.raises(ModelError, match="INPUT has 3 elements; size is 2"):
        load_body(tmp_path, '<module class="Constant" name="B" data="1 2 3"/>'
                  '<module class="ActionCompetition" name="AC" size="2"/>'
                  '<connection source="B.OUTPUT" target="AC.INPUT"/>')
    with pytest.raises(ModelError, match="duration has 2 values"):
        load_body(tmp_path, '<module class="ActionCompetition" name="AC" size="3" '
                  'duration="1 2"/>')
