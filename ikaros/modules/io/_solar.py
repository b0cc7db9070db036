"""The sun's position, by the formulas of NOAA's Solar Calculator (Global Monitoring
Laboratory; from Jean Meeus, Astronomical Algorithms), without atmospheric refraction."""
from __future__ import annotations

import calendar
import math
from datetime import datetime


def julian_century(when: datetime) -> float:
    """Julian centuries since J2000.0 of a UTC time (a naive datetime is taken as UTC)."""
    seconds = calendar.timegm(when.utctimetuple()) + when.microsecond / 1e6
    julian_day = 2440587.5 + seconds / 86400.0
    return (julian_day - 2451545.0) / 36525.0


def sun(when: datetime) -> tuple[float, float]:
    """The sun's declination (degrees) and the equation of time (minutes) at ``when``."""
    t = julian_century(when)
    mean_longitude = (280.46646 + t * (36000.76983 + t * 0.0003032)) % 360.0
    anomaly = 357.52911 + t * (35999.05029 - 0.0001537 * t)
    eccentricity = 0.016708634 - t * (0.000042037 + 0.0000001267 * t)
    m = math.radians(anomaly)
    centre = (math.sin(m) * (1.914602 - t * (0.004817 + 0.000014 * t))
              + math.sin(2 * m) * (0.019993 - 0.000101 * t) + math.sin(3 * m) * 0.000289)
    omega = math.radians(125.04 - 1934.136 * t)
    apparent_longitude = mean_longitude + centre - 0.00569 - 0.00478 * math.sin(omega)
    mean_obliquity = 23 + (26 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60) / 60
    obliquity = math.radians(mean_obliquity + 0.00256 * math.cos(omega))
    declination = math.degrees(math.asin(math.sin(obliquity)
                                         * math.sin(math.radians(apparent_longitude))))
    y = math.tan(obliquity / 2) ** 2
    l0 = math.radians(mean_longitude)
    equation_of_time = 4 * math.degrees(
        y * math.sin(2 * l0) - 2 * eccentricity * math.sin(m)
        + 4 * eccentricity * y * math.sin(m) * math.cos(2 * l0)
        - 0.5 * y * y * math.sin(4 * l0) - 1.25 * eccentricity ** 2 * math.sin(2 * m))
    return declination, equation_of_time


def elevation(when: datetime, latitude: float, longitude: float) -> float:
    """The sun's elevation above the horizon in degrees at a UTC time, at a latitude
    (degrees north) and longitude (degrees east)."""
    declination, equation_of_time = sun(when)
    minutes = when.hour * 60 + when.minute + (when.second + when.microsecond / 1e6) / 60
    solar_time = (minutes + equation_of_time + 4 * longitude) % 1440.0
    hour_angle = math.radians(solar_time / 4 - 180)
    lat, dec = math.radians(latitude), math.radians(declination)
    cos_zenith = math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * math.cos(hour_angle)
    return 90.0 - math.degrees(math.acos(max(-1.0, min(1.0, cos_zenith))))
