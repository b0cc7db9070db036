"""Tests of Perception: what is perceived, and how often and where the gaze goes, in this
project's scan of objects and in Ikaros 2's (golden-v2 Perception; the C library's rand())."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

ENV = "1 0 1; 0 1 0; 0 0 0"           # 3 objects x 3 properties; object 2 has none
FEATURES = "1 0 0 0; 0 1 0 0; 0 0 1 1"  # 3 properties x 4 features


def build(params, location=None):
    text = (f'<module class="Constant" name="E" data="{ENV}"/>'
            f'<module class="Constant" name="F" data="{FEATURES}"/>'
            f'<module class="Perception" name="P" scan="objects" {params}/>'
            '<connection source="E.OUTPUT" target="P.ENVIRONMENT" delay="0"/>'
            '<connection source="F.OUTPUT" target="P.FEATURES" delay="0"/>')
    if location:
        text += (f'<module class="Constant" name="L" data="{location}"/>'
                 '<connection source="L.OUTPUT" target="P.LOCATION_IN" delay="0"/>')
    return text


def run(tmp_path, ticks, params, location=None):
    net = load(tmp_path, build(params, location))
    try:
        assert net.output("P.LOCATION_OUT").shape == (3,)
        assert net.output("P.OUTPUT").shape == (4,)
        locs, outs = [], []
        for _ in range(ticks):
            net.step()
            locs.append(net.output("P.LOCATION_OUT").copy())
            outs.append(net.output("P.OUTPUT").copy())
        return np.array(locs), np.array(outs)
    finally:
        net.close()


def test_perceives_only_properties_of_the_attended_object(tmp_path):
    locs, outs = run(tmp_path, 600, 'seed="1"')
    env = np.array([[1, 0, 1], [0, 1, 0], [0, 0, 0]])
    feats = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1]])
    assert np.all(locs.sum(axis=1) == 1)
    for loc, out in zip(locs, outs):
        obj = int(np.argmax(loc))
        allowed = [feats[p] for p in np.flatnonzero(env[obj])] or [np.zeros(4)]
        assert any(np.array_equal(out, a) for a in allowed)
    # uniform over objects: each about 1/3 of 600 (binomial sd ~ 11.5)
    assert np.all(np.abs(locs.sum(axis=0) - 200) < 60)
    # object 0 shows both its properties
    seen = {tuple(o) for loc, o in zip(locs, outs) if loc[0]}
    assert seen == {(1, 0, 0, 0), (0, 0, 1, 1)}


def test_interval_sets_the_rate_of_shifts(tmp_path):
    locs, outs = run(tmp_path, 2000, 'seed="2" interval="10"')
    changed = np.any(np.diff(np.concatenate([locs, outs], axis=1), axis=0) != 0, axis=1)
    # a shift happens with probability 0.1 per tick (and may repeat the same view)
    assert 0.03 < changed.mean() < 0.1


def test_location_in_biases_the_gaze(tmp_path):
    # weights 1 + 4 * (0, 1, 0)^2 = 1, 5, 1: object 1 chosen with probability 5/7
    locs, _ = run(tmp_path, 1400, 'seed="3" phi="4"', location="0 1 0")
    assert locs[:, 1].mean() == pytest.approx(5 / 7, abs=0.05)


def test_same_seed_same_run(tmp_path):
    a = run(tmp_path, 50, 'seed="7" interval="3"')
    b = run(tmp_path, 50, 'seed="7" interval="3"')
    assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1])


# --- scan="original" (Ikaros 2) ---------------------------------------------------------------

GLIBC_1 = [1804289383, 846930886, 1681692777, 1714636915, 1957747793, 424238335,
           719885386, 1649760492, 596516649, 1189641421, 1025202362, 1350490027]


def original(tmp_path, ticks, params="", location=None):
    body = ('<module class="Constant" name="E" data="1 1; 1 1"/>'
            '<module class="Constant" name="F" data="1 2 3 4 5; 6 7 8 9 10; 11 12 13 14 15"/>'
            f'<module class="Perception" name="P" {params}/>'
            '<connection source="E.OUTPUT" target="P.ENVIRONMENT" delay="0"/>'
            '<connection source="F.OUTPUT" target="P.FEATURES" delay="0"/>')
    if location:
        body += (f'<module class="Constant" name="L" data="{location}"/>'
                 '<connection source="L.OUTPUT" target="P.LOCATION_IN" delay="0"/>')
    net = load(tmp_path, body)
    try:
        assert net.output("P.LOCATION_OUT").shape == (2,) and net.output("P.OUTPUT").shape == (8,)
        out = []
        for _ in range(ticks):
            net.step()
            out.append((net.output("P.LOCATION_OUT").copy(), net.output("P.OUTPUT").copy()))
        return out
    finally:
        net.close()


def test_original_scan_draws_three_numbers_a_tick(tmp_path):
    """Per tick: a shift draw, the location rand() % 2, the row rand() % 3 of FEATURES; OUTPUT
    is 8 values from that row's start, 0 past the end of FEATURES."""
    flat = np.arange(1, 16, dtype=float)
    for t, (loc, out) in enumerate(original(tmp_path, 4)):
        location, row = GLIBC_1[3 * t + 1] % 2, GLIBC_1[3 * t + 2] % 3
        assert loc.tolist() == [1 - location, location]
        expected = np.zeros(8)
        part = flat[5 * row:5 * row + 8]
        expected[:part.size] = part
        assert out.tolist() == expected.tolist()


def test_original_scan_interval_and_seed(tmp_path):
    # interval 4: a shift when rand()/RAND_MAX < 1/4; the first draws of seed 1 are above
    out = original(tmp_path, 3, 'interval="4"')
    assert [o[0].sum() for o in out] == [0, 0, 0]          # 0.840, 0.394, 0.783: no shift
    a = original(tmp_path, 20, 'seed="9"')
    b = original(tmp_path, 20, 'seed="9"')
    assert all(np.array_equal(x[1], y[1]) for x, y in zip(a, b))


def test_original_scan_location_in_biases_the_location(tmp_path):
    out = original(tmp_path, 400, 'phi="8"', location="0 1")     # weights 1 : 9
    share = np.mean([o[0][1] for o in out])
    assert 0.83 < share < 0.97
