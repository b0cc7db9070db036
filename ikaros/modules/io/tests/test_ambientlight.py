"""AmbientLight against published facts of the sun's position: the equation of time is
about -14.2 minutes around 11 February and +16.4 minutes around 3 November, the sun's
declination is about +23.44° at the June solstice and near 0° at the equinoxes, and at
solar noon the sun stands 90° - latitude + declination high."""
import math
from datetime import datetime, timedelta

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.modules.io import _solar
from ikaros.testing import load_body as load


def test_declination_and_equation_of_time_at_known_dates():
    assert _solar.sun(datetime(2024, 6, 20, 20, 51))[0] == pytest.approx(23.44, abs=0.01)
    assert abs(_solar.sun(datetime(2024, 3, 20, 3, 6))[0]) < 0.01           # the equinox
    assert _solar.sun(datetime(2024, 2, 11, 12))[1] == pytest.approx(-14.2, abs=0.1)
    assert _solar.sun(datetime(2024, 11, 3, 12))[1] == pytest.approx(16.4, abs=0.1)


def solar_noon(day: datetime, longitude: float) -> datetime:
    """UTC solar noon: 12:00 minus 4 minutes a degree east, minus the equation of time."""
    equation = _solar.sun(day.replace(hour=12))[1]
    return day + timedelta(minutes=720 - 4 * longitude - equation)


@pytest.mark.parametrize("latitude, longitude", [(55.7, 13.2), (0.0, -60.0), (-33.9, 151.2)])
def test_the_noon_sun_stands_at_90_minus_latitude_plus_declination(latitude, longitude):
    noon = solar_noon(datetime(2024, 6, 21), longitude)
    declination = _solar.sun(noon)[0]
    assert _solar.elevation(noon, latitude, longitude) == pytest.approx(
        90 - abs(latitude - declination), abs=0.02)
    midnight = noon + timedelta(hours=12)
    assert _solar.elevation(midnight, latitude, longitude) < 0 or latitude > 66 - 23.5


def light(tmp_path, attrs, ticks, **top):
    net = load(tmp_path, f'<module class="AmbientLight" name="L" {attrs}/>', **top)
    out = []
    try:
        for _ in range(ticks):
            net.step()
            out.append(float(net.output("L.OUTPUT")[0]))
    finally:
        net.close()
    return out


def test_direct_light_through_a_day_in_lund(tmp_path):
    # one tick an hour from midnight UTC on 21 June 2024 at Lund (55.7° N, 13.2° E)
    got = light(tmp_path, 'year="2024" month="6" day="21" latitude="55.7" longitude="13.2" '
                          'radiation="800"', 24, tick_duration="3600", dialect="2")
    expected = []
    for hour in range(24):                  # Ikaros 2 files: tick k is at k hours
        e = _solar.elevation(datetime(2024, 6, 21, hour), 55.7, 13.2)
        expected.append(800 * math.sin(math.radians(e)) if e > 0 else 0.0)
    assert np.allclose(got, expected, rtol=1e-5)
    assert got[0] == 0 and got[11] > 650                    # night, and near noon
    assert max(got) == pytest.approx(800 * math.sin(math.radians(90 - 55.7 + 23.44)),
                                     rel=0.01)


def test_on_off_and_the_time_of_day(tmp_path):
    got = light(tmp_path, 'method="OnOff" year="2024" month="6" day="21" time="1" '
                          'latitude="55.7" longitude="13.2" radiation="2"', 3,
                tick_duration="3600", dialect="2")
    # 01:00, 02:00, 03:00 UTC: the sun rises at Lund at about 02:25 UTC (04:25 summer time)
    assert got == [0, 0, 2]


def test_the_system_clock(tmp_path):
    got = light(tmp_path, 'use_system_time="yes" latitude="0" longitude="0"', 1)
    assert 0 <= got[0] <= 1


def test_a_date_that_does_not_exist_is_a_load_error(tmp_path):
    with pytest.raises(ModelError, match="2023-2-29 is not a date"):
        light(tmp_path, 'year="2023" month="2" day="29"', 1)
