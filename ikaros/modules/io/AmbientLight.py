"""AmbientLight: the daylight at a place and time, from the sun's position."""
import math
from datetime import datetime, timedelta, timezone

from ikaros.module import Module, Output, Parameter

from . import _solar


class AmbientLight(Module):
    """The light of the sun at a place (Ikaros 3's class, written here from its interface;
    the light is this project's reading): OUTPUT is ``radiation`` × sin(elevation) while
    the sun is above the horizon, else 0 (``method`` DSR, direct solar radiation on a level
    surface), or ``radiation`` while the sun is up and 0 when it is down (OnOff). The sun's
    elevation comes from the formulas of NOAA's Solar Calculator (after Meeus), without
    refraction, at ``latitude`` (degrees north) and ``longitude`` (degrees east). The time
    is the computer's clock (``use_system_time``), or the date ``year``-``month``-``day`` at
    ``time`` hours (UTC) plus the model's time (tick × tick_duration), so that a model runs
    through days. As Ikaros 3 declares them, the defaults are longitude 55.577918 and
    latitude 12.814571, a point in the Arabian Sea; the numbers look like Lund's latitude
    and longitude swapped, but here each is taken as what its name says."""

    method = Parameter("DSR", "DSR: radiation × sin(elevation); OnOff: radiation while the "
                       "sun is up", options="DSR,OnOff")
    use_system_time = Parameter(False, "use the computer's clock instead of the date and time")
    year = Parameter(2024, "the year of the start", type="int")
    month = Parameter(1, "the month of the start, 1 to 12", type="int", range=(1, 12))
    day = Parameter(1, "the day of the month of the start", type="int", range=(1, 31))
    time = Parameter(0.0, "the time of day of the start, hours UTC")
    radiation = Parameter(1.0, "the light when the sun is straight overhead (DSR) or up "
                          "(OnOff)")
    longitude = Parameter(55.577918, "degrees east")
    latitude = Parameter(12.814571, "degrees north", range=(-90, 90))
    OUTPUT = Output("the light", size="1")

    def configure(self):
        try:
            datetime(self.year, self.month, self.day)
        except ValueError as e:
            raise ValueError(f"{self.year}-{self.month}-{self.day} is not a date: {e}") \
                from None

    def now(self) -> datetime:
        """The time of this tick (UTC)."""
        if self.use_system_time:
            return datetime.now(timezone.utc)
        return datetime(self.year, self.month, self.day, tzinfo=timezone.utc) + \
            timedelta(hours=self.time, seconds=self.clock.time)

    def tick(self):
        elevation = _solar.elevation(self.now(), self.latitude, self.longitude)
        if elevation <= 0:
            self.OUTPUT[0] = 0
        elif self.method == "OnOff":
            self.OUTPUT[0] = self.radiation
        else:
            self.OUTPUT[0] = self.radiation * math.sin(math.radians(elevation))
