"""EnergyMeter: power and energy from a smart plug's HTTP status page (Ikaros 3)."""
import re
import urllib.request

from ikaros.module import Module, Output, Parameter

_POWER = re.compile(rb'"power"\s*:\s*(-?[0-9.]+(?:[eE][-+]?[0-9]+)?)')


class EnergyMeter(Module):
    """Reads a smart plug's status page every tick (an HTTP GET of ``address``; ``http://``
    is added when it has no scheme) and puts the number after ``"power":`` in
    MEASURED_POWER. ENERGY then grows by tick_duration·MEASURED_POWER/(1000·1000·3600),
    the factor Ikaros 3 uses (its comment says watt-hours, but the divisor is a million
    times larger). When the page cannot be read or has no power, ENERGY is set to 0 and
    MEASURED_POWER keeps its value, as in Ikaros 3. A GET that takes longer than
    ``timeout`` seconds fails (this project's addition: the tick waits for it). New in
    Ikaros 3."""

    address = Parameter("192.168.33.1/status", "the status URL of the smart plug")
    timeout = Parameter(1.0, "seconds a request may take", range=(0.001, None))
    MEASURED_POWER = Output("the power on the status page", size="1")
    ENERGY = Output("the energy since the start (Ikaros 3's units)", size="1")

    def init(self):
        self._url = self.address if "://" in self.address else "http://" + self.address
        self._warned = False

    def _power(self):
        try:
            with urllib.request.urlopen(self._url, timeout=self.timeout) as reply:
                found = _POWER.search(reply.read())
        except (OSError, ValueError) as e:
            if not self._warned:
                self.warning(f"cannot read {self._url}: {e}")
                self._warned = True
            return None
        return float(found.group(1)) if found else None

    def tick(self):
        power = self._power()
        if power is None:
            self.ENERGY[0] = 0
        else:
            self.MEASURED_POWER[0] = power
        self.ENERGY[0] += self.clock.tick_duration * self.MEASURED_POWER[0] / \
            (1000 * 1000 * 3600)
